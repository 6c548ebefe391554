#![allow(missing_docs)] // criterion_group! generates an undocumented function
//! Front-end speed: parse + evaluate `#while`-generated sphere scenes.
//! Targets (issue 2): 10,000 spheres in ≤ 10 ms, 1,000,000 in ≤ 1 s under 300 MB.
//! Run with `cargo bench --bench frontend`.

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

criterion_group!(benches, spheres);
criterion_main!(benches);
