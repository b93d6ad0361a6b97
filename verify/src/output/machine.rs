//! The machine a figure was measured on: CPU model, logical cores and the vector extensions
//! the pair loops can use (speed differs between machines; a figure without them is not
//! comparable).

/// E.g. `AMD EPYC 7B13 64-Core Processor, 2 logical cores, avx2 fma (no avx512f)`; what
/// `/proc/cpuinfo` does not say is left out.
pub fn describe() -> String {
    let info = std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default();
    let field = |name: &str| {
        info.lines()
            .find(|l| l.split(':').next().is_some_and(|k| k.trim() == name))
            .and_then(|l| l.split_once(':'))
            .map(|(_, v)| v.trim().to_string())
    };
    let cores = std::thread::available_parallelism().map_or(0, |n| n.get());
    let model = field("model name").unwrap_or_else(|| std::env::consts::ARCH.to_string());
    let flags = field("flags").unwrap_or_default();
    let flags: Vec<&str> = flags.split_whitespace().collect();
    let wanted = ["avx2", "fma", "avx512f"];
    let have: Vec<&str> = wanted
        .iter()
        .copied()
        .filter(|f| flags.contains(f))
        .collect();
    let lacking: Vec<&str> = wanted
        .iter()
        .copied()
        .filter(|f| !flags.contains(f))
        .collect();
    let mut s = format!("{model}, {cores} logical cores");
    if !flags.is_empty() {
        s.push_str(&format!(", {}", have.join(" ")));
        if !lacking.is_empty() {
            s.push_str(&format!(" (no {})", lacking.join(", ")));
        }
    }
    s
}

#[cfg(test)]
mod tests {
    #[test]
    fn names_the_cores() {
        assert!(super::describe().contains("logical cores"));
    }
}
