#![allow(missing_docs)] // criterion_group! generates an undocumented function
//! Sampling cost: `examples/showcase.rts` at 160 × 120, one ray per pixel, with
//! POV-Ray's adaptive anti-aliasing (`+A0.3`) and with 4 samples per pixel. The
//! throughput is counted in camera pixels; `rts render --stats-json` gives rays/s.
//! Run with `cargo bench --bench sampling`.

mod common;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use rts::render::{render_with, Antialias, RenderOptions, Sampling, Settings};

fn showcase() -> rts::build::World {
    common::example_world("showcase.rts")
}

fn render(c: &mut Criterion) {
    let world = showcase();
    let opts = RenderOptions {
        width: 160,
        height: 120,
    };
    let mut g = c.benchmark_group("showcase 160x120");
    g.sample_size(20);
    g.throughput(Throughput::Elements(160 * 120));
    for (name, sampling) in [
        ("1 ray per pixel", Sampling::Centre),
        ("antialias 0.3", Sampling::Adaptive(Antialias::default())),
        ("4 samples", Sampling::Fixed(4)),
    ] {
        let settings = Settings {
            sampling,
            ..Settings::default()
        };
        g.bench_function(name, |b| {
            b.iter(|| {
                render_with(&world, &opts, &settings, None)
                    .stats
                    .rays
                    .total()
            })
        });
    }
    g.finish();
}

criterion_group!(benches, render);
criterion_main!(benches);
