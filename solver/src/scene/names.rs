//! "Did you mean": the known name nearest to one a scene does not define.

/// The message for a name no `[[kind]]` defines: the nearest of `known` when one is close (the
/// same letters in another case, or at most a third of its letters edited, at least 2), and the
/// names there are.
pub(crate) fn no_such<'a>(kind: &str, name: &str, known: impl Iterator<Item = &'a str>) -> String {
    let known: Vec<&str> = known.collect();
    let mut msg = format!("no [[{kind}]] has this name");
    if let Some(near) = nearest(name, &known) {
        msg.push_str(&format!("; did you mean \"{near}\"?"));
    }
    if known.is_empty() {
        msg.push_str(&format!(" (the scene has no [[{kind}]])"));
    } else {
        msg.push_str(&format!(" ({kind}s: {})", known.join(", ")));
    }
    msg
}

/// The known name closest to `name`, if close enough to be a slip.
fn nearest<'a>(name: &str, known: &[&'a str]) -> Option<&'a str> {
    if let Some(k) = known.iter().find(|k| k.eq_ignore_ascii_case(name)) {
        return Some(k);
    }
    let limit = (name.chars().count() / 3).max(2);
    known
        .iter()
        .map(|k| (edits(&name.to_lowercase(), &k.to_lowercase()), *k))
        .filter(|(d, _)| *d <= limit)
        .min_by_key(|(d, _)| *d)
        .map(|(_, k)| k)
}

/// Levenshtein distance (insertions, deletions, substitutions) between `a` and `b`.
fn edits(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_slip_gets_the_nearest_name_and_a_stranger_only_the_list() {
        let known = ["water", "oil"];
        let m = no_such("liquid", "Water", known.into_iter());
        assert!(
            m.contains("did you mean \"water\"") && m.ends_with("(liquids: water, oil)"),
            "{m}"
        );
        assert!(no_such("liquid", "watr", known.into_iter()).contains("\"water\""));
        assert!(!no_such("liquid", "mercury", known.into_iter()).contains("did you mean"));
        let none = no_such("solid", "glass", std::iter::empty());
        assert!(none.ends_with("(the scene has no [[solid]])"), "{none}");
        assert_eq!(edits("kitten", "sitting"), 3);
        assert_eq!(edits("", "abc"), 3);
    }
}
