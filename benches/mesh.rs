#![allow(missing_docs)] // criterion_group! generates an undocumented function
//! Mesh speed: BVH build over a 1M-triangle mesh and primary-ray throughput.
//! Targets (issue 3): build ≤ 0.4 s, ≥ 5 Mrays/s on 2 cores, ≤ 120 MB for the mesh.
//! Run with `cargo bench --bench mesh`; the setup prints peak memory (VmHWM),
//! and CPU seconds next to wall time, since a shared machine's wall times vary.
//! Measured (2026-11, a 2-core machine under load ≈ 5): one build 0.50 s wall /
//! 0.52 CPU s; primary rays 1.9 Mrays/s wall, 1.87 Mrays per CPU second; peak
//! memory 104 MB for the whole process (mesh 18 MB, BVH 22 MB).
//! After the plain-comparison slab test (2026-11-21, load ≈ 4 on 2 cores, so
//! wall ≈ CPU): build 0.50 s / 0.55 CPU s (unchanged); primary rays
//! 2.0 Mrays/s, 1.98 Mrays per CPU second (was 1.87); peak 103 MB.
//! Idle machine after the 32-entry traversal stack (2026-11-22): build 0.45 s wall /
//! 0.72 CPU s; primary rays 1,048,576 in 0.243 s wall = 4.3 Mrays/s (2.23 Mrays per
//! CPU second); peak 110 MB. With the root passes binned in parallel chunks: build
//! 0.27 s (criterion "BVH build", idle), 0.28-0.32 s wall in the setup line.
//! 2026-11-22, idle, after the world-tree changes of the path tracer work: build
//! 0.27 s (criterion), primary rays 4.38 Mrays/s (2.28 Mrays per CPU second),
//! peak 98 MB. Keeping entry distances on the traversal stack gave 3.92 Mrays/s
//! (dropped).
//! 2026-11-22, idle, after the 4-wide walk for meshes (src/build/wide.rs): build
//! 0.28 s (criterion), primary rays 5.09-5.10 Mrays/s in two runs (2.69 Mrays per
//! CPU second), peak 100 MB (BVH 21 MB).
//! 2026-11-28, load 5-7 on 2 cores (so per CPU second is the number to read),
//! back to back with main's binary: 8-wide nodes (src/build/accel, pulp kernels)
//! 3.00-3.28 Mrays per CPU second at AVX-512 and AVX2, 2.44 at the scalar
//! level (`RTS_SIMD=scalar`), against 3.08-3.28 for the 4-wide walk; build
//! 0.41-0.44 CPU s both (same builder); peak 97-103 MB against 103-104 (BVH 27 MB
//! against 21: 8-wide nodes are less full). The f32 cull of leaf triangles
//! measured 2.6-2.8 (leaves of 4) and 2.5 (leaves of 8): off. Embree 4 on the
//! same mesh and rays (tests/compare/embree_mesh.py): 5.3-5.5 Mrays per CPU
//! second, 3.5 Mrays/s on 1 thread, 4.9 on 2; build + first ray 0.92 s.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use glam::DVec3;
use rayon::prelude::*;
use rts::build::mesh::MeshAccel;
use rts::build::{build, Ray, RayKind, World};
use rts::scene::{MeshData, Object, Scene, Shape};
use rts::span::Span;
use std::sync::Arc;

/// A wavy grid of `2 n²` triangles over [-1, 1]².
fn grid(n: u32) -> MeshData {
    let mut m = MeshData::default();
    let v = n + 1;
    for j in 0..v {
        for i in 0..v {
            let (x, z) = (
                i as f32 / n as f32 * 2.0 - 1.0,
                j as f32 / n as f32 * 2.0 - 1.0,
            );
            m.positions
                .push([x, 0.1 * (x * 20.0).sin() * (z * 17.0).cos(), z]);
        }
    }
    m.triangles.reserve(2 * (n * n) as usize);
    for j in 0..n {
        for i in 0..n {
            let k = j * v + i;
            m.triangles.push([k, k + 1, k + v]);
            m.triangles.push([k + 1, k + v + 1, k + v]);
        }
    }
    m
}

/// CPU seconds this process has used (user + system), to report work done
/// independently of how busy the machine is.
fn cpu_seconds() -> f64 {
    std::fs::read_to_string("/proc/self/stat")
        .ok()
        .and_then(|s| {
            let f: Vec<&str> = s.rsplit(')').next()?.split_whitespace().collect();
            Some((f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?) / 100.0)
        })
        .unwrap_or(0.0)
}

fn peak_mb() -> f64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM"))
                .and_then(|l| l.split_whitespace().nth(1)?.parse::<f64>().ok())
        })
        .map_or(0.0, |kb| kb / 1024.0)
}

/// Primary rays over a `res`² image looking down at the grid; returns hits.
fn primary(world: &World, res: u32) -> usize {
    (0..res)
        .into_par_iter()
        .map(|j| {
            let mut hits = 0;
            for i in 0..res {
                let target = DVec3::new(
                    i as f64 / res as f64 * 2.0 - 1.0,
                    0.0,
                    j as f64 / res as f64 * 2.0 - 1.0,
                );
                let o = DVec3::new(0.0, 3.0, -2.0);
                let ray = Ray::new(o, (target - o).normalize());
                hits += world
                    .intersect(&ray, 0.0, f64::INFINITY, RayKind::Camera)
                    .is_some() as usize;
            }
            hits
        })
        .sum()
}

fn mesh(c: &mut Criterion) {
    let base = peak_mb();
    let data = Arc::new(grid(708)); // 1,002,528 triangles
    let (t, cpu) = (std::time::Instant::now(), cpu_seconds());
    let accel = MeshAccel::new(data.clone());
    eprintln!(
        "1M-triangle mesh: {} triangles, {} vertices, one build {:?} ({:.2} CPU s), peak memory {:.0} MB (+{:.0} MB over start), BVH {:.0} MB",
        data.triangles.len(),
        data.positions.len(),
        t.elapsed(),
        cpu_seconds() - cpu,
        peak_mb(),
        peak_mb() - base,
        accel.bvh.memory() as f64 / 1048576.0
    );
    drop(accel);
    let mut g = c.benchmark_group("mesh 1M triangles");
    g.sample_size(10);
    g.bench_function("BVH build", |b| b.iter(|| MeshAccel::new(data.clone())));
    let scene = Scene {
        objects: vec![Object::new(Shape::Mesh(data.clone()), Span::default())],
        ..Scene::default()
    };
    let world = build(&scene);
    let res = 1024u32;
    let (t, cpu) = (std::time::Instant::now(), cpu_seconds());
    let hits = primary(&world, res);
    let cpu = cpu_seconds() - cpu;
    eprintln!(
        "primary rays: {} rays ({hits} hits) in {:?} wall, {cpu:.2} CPU s: {:.2} Mrays per CPU second",
        res * res,
        t.elapsed(),
        (res * res) as f64 / cpu.max(1e-9) / 1e6
    );
    g.throughput(Throughput::Elements((res * res) as u64));
    g.bench_function("primary rays (elements = rays)", |b| {
        b.iter(|| primary(&world, res))
    });
    g.finish();
}

criterion_group!(benches, mesh);
criterion_main!(benches);
