//! Criterion settings shared by the benchmark targets (not a target itself).

use benches::Sampling;
use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, SamplingMode};

/// Applies a problem size's sampling settings to the benchmarks added next to `group`.
pub fn configure(group: &mut BenchmarkGroup<'_, WallTime>, s: Sampling) {
    group
        .sample_size(s.sample_size)
        .warm_up_time(s.warm_up)
        .measurement_time(s.measurement)
        .sampling_mode(if s.flat {
            SamplingMode::Flat
        } else {
            SamplingMode::Auto
        });
}
