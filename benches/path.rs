#![allow(missing_docs)] // criterion_group! generates an undocumented function
//! Path tracing cost: `examples/cornell_box.rts` (Mitsuba 3's Cornell box) at
//! 64 × 64, 4 samples per pixel, max depth 8, with the splatted Gaussian filter
//! and with the box filter. The throughput is counted in camera samples.
//! Run with `cargo bench --bench path`; for noise-free numbers use callgrind on
//! `rts render examples/cornell_box.rts --integrator path --spp 4 --threads 1`
//! (see docs/pathtracing.md, "Speed").

mod common;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use rts::render::path::{self, PathOptions};
use rts::render::{RenderOptions, Settings};
use rts::scene::PixelFilter;

fn cornell() -> rts::build::World {
    common::example_world("cornell_box.rts")
}

fn render(c: &mut Criterion) {
    let world = cornell();
    let (w, h, spp) = (64, 64, 4);
    let opts = RenderOptions {
        width: w,
        height: h,
    };
    let mut g = c.benchmark_group("cornell box 64x64, 4 spp");
    g.sample_size(10);
    g.throughput(Throughput::Elements(u64::from(w * h * spp)));
    for (name, filter) in [
        ("gaussian (splatted)", PixelFilter::Gaussian),
        ("box", PixelFilter::Box),
    ] {
        let popts = PathOptions {
            filter,
            ..PathOptions::default()
        };
        g.bench_function(name, |b| {
            b.iter(|| {
                path::render(&world, &opts, &Settings::default(), &popts, spp)
                    .stats
                    .samples
            })
        });
    }
    g.finish();
}

criterion_group!(benches, render);
criterion_main!(benches);
