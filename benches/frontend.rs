#![allow(missing_docs)] // criterion_group! generates an undocumented function
//! Front-end speed: parse + evaluate `#while`-generated sphere scenes, and a
//! large `mesh2` as modelling tools export it (bulk literal data).
//! Targets: 10,000 spheres in ≤ 10 ms, 1,000,000 in ≤ 1 s under 300 MB; the
//! 708 × 708 grid `mesh2` (1M triangles, 36 MB of text) in ≤ 1 s under 300 MB.
//! Run with `cargo bench --bench frontend`; the grid case prints the process's
//! peak memory after one run.

use criterion::{criterion_group, criterion_main, Criterion};
use rts::eval::{eval, EvalOptions};
use rts::source::SourceMap;

fn scene(n: u32) -> String {
    format!(
        "#declare I = 0;\n#while (I < {n})\n  sphere {{ <mod(I, 1000), div(I, 1000), 0>, 0.4 }}\n  #declare I = I + 1;\n#end\n"
    )
}

fn parse_and_eval(text: &str) -> usize {
    let mut sources = SourceMap::new();
    let id = sources.add("bench.rts", None, text.to_string());
    let (file, _) = rts::syntax::parse(text, id);
    eval(&file, id, &mut sources, &EvalOptions::default())
        .scene
        .objects
        .len()
}

fn spheres(c: &mut Criterion) {
    let small = scene(10_000);
    c.bench_function("parse+eval 10k spheres", |b| {
        b.iter(|| parse_and_eval(&small))
    });
    let big = scene(1_000_000);
    let mut g = c.benchmark_group("large");
    g.sample_size(10);
    g.bench_function("parse+eval 1M spheres", |b| b.iter(|| parse_and_eval(&big)));
    g.finish();
}

/// The text `benches/mesh2_grid.py N` writes: an `n` × `n` height-field grid
/// as `#declare Terrain = mesh2 { vertex_vectors … face_indices … }`, 5 decimals.
fn mesh2_grid(n: usize) -> String {
    use std::fmt::Write;
    let mut s = String::with_capacity(n * n * 75);
    let _ = write!(
        s,
        "#declare Terrain = mesh2 {{\n  vertex_vectors {{\n    {},\n",
        n * n
    );
    for j in 0..n {
        for i in 0..n {
            let x = i as f64 / (n - 1) as f64 * 10.0 - 5.0;
            let z = j as f64 / (n - 1) as f64 * 10.0 - 5.0;
            let y = 0.5 * (x * 1.3).sin() * (z * 0.7).cos();
            let _ = writeln!(s, "    <{x:.5}, {y:.5}, {z:.5}>,");
        }
    }
    let _ = write!(
        s,
        "  }}\n  face_indices {{\n    {},\n",
        2 * (n - 1) * (n - 1)
    );
    for j in 0..n - 1 {
        for i in 0..n - 1 {
            let a = j * n + i;
            let (b, c) = (a + 1, a + n);
            let d = c + 1;
            let _ = writeln!(s, "    <{a}, {b}, {d}>, <{a}, {d}, {c}>,");
        }
    }
    s.push_str("  }\n}\nobject { Terrain }\n");
    s
}

/// The process's peak resident memory in MiB (Linux), for the report.
fn peak_mib() -> Option<f64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib / 1024.0)
}

fn bulk_data(c: &mut Criterion) {
    let grid = mesh2_grid(708);
    let mut g = c.benchmark_group("bulk data");
    g.sample_size(10);
    g.bench_function("parse+eval mesh2 708x708 grid (36 MB)", |b| {
        b.iter(|| parse_and_eval(&grid))
    });
    g.finish();
    if let Some(mib) = peak_mib() {
        println!("peak memory after the mesh2 grid runs: {mib:.0} MiB");
    }
}

criterion_group!(benches, spheres, bulk_data);
criterion_main!(benches);
