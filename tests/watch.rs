//! `rts watch`: a change to the scene (saved by rename, as editors do) or to a file it
//! includes produces a new image; a broken scene keeps the last good one.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Waits until `out` exists with contents other than `old`; returns them.
fn wait_for_change(out: &Path, old: &[u8]) -> Vec<u8> {
    let start = Instant::now();
    loop {
        if let Ok(b) = std::fs::read(out) {
            if b != old && image::load_from_memory(&b).is_ok() {
                return b;
            }
        }
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "{} did not change within 60 s",
            out.display()
        );
        std::thread::sleep(Duration::from_millis(50));
    }
}

/// Saves `text` as `path` the way editors do: write a temporary file, rename it over.
fn save(path: &Path, text: &str) {
    let tmp = path.with_extension("tmp~");
    std::fs::write(&tmp, text).expect("write");
    std::fs::rename(&tmp, path).expect("rename");
}

fn centre_red(png: &[u8]) -> u8 {
    let img = image::load_from_memory(png).expect("png").to_rgb8();
    img.get_pixel(img.width() / 2, img.height() / 2)[0]
}

#[test]
fn a_change_renders_a_new_image() {
    let dir = std::env::temp_dir().join(format!("rts-watch-test-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("dir");
    let scene = dir.join("scene.rts");
    let colour = dir.join("colour.inc");
    let out = dir.join("preview.png");
    std::fs::write(&colour, "#declare C = rgb <1, 0, 0>;\n").expect("write");
    let text = "global_settings { assumed_gamma 1.0 }\n#include \"colour.inc\"\n\
camera { location <0, 0, -5> look_at 0 }\n\
light_source { <0, 0, -10> rgb 1 }\n\
sphere { 0, 1.5 pigment { C } finish { ambient 1 diffuse 0 } }\n";
    std::fs::write(&scene, text).expect("write");
    let mut child = Command::new(env!("CARGO_BIN_EXE_rts"))
        .args([
            "watch",
            "-W",
            "32",
            "-H",
            "24",
            "--antialias",
            "0",
            "--debounce",
            "50",
            "-o",
        ])
        .arg(&out)
        .arg(&scene)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("spawn rts watch");
    let result = std::panic::catch_unwind(|| {
        let first = wait_for_change(&out, &[]);
        assert!(centre_red(&first) > 200);
        // Wait for the full-quality pass too, so it does not land after the change.
        std::thread::sleep(Duration::from_millis(300));
        let first = std::fs::read(&out).expect("read");

        // The included file changes: the sphere turns blue.
        save(&colour, "#declare C = rgb <0, 0, 1>;\n");
        wait_for_change(&out, &first);
        std::thread::sleep(Duration::from_millis(300));
        let second = std::fs::read(&out).expect("read");
        assert!(centre_red(&second) < 50);

        // A broken scene keeps the last good image.
        save(&scene, &text.replace("sphere {", "sphere { oops"));
        std::thread::sleep(Duration::from_millis(1500));
        assert_eq!(std::fs::read(&out).expect("read"), second);

        // Fixed again (saved by rename): a new image.
        save(&scene, &text.replace("1.5", "0.5"));
        wait_for_change(&out, &second);

        // Then nothing more happens: reading the files does not trigger renders.
        std::thread::sleep(Duration::from_millis(500));
        let settled = std::fs::metadata(&out)
            .expect("out")
            .modified()
            .expect("mtime");
        std::thread::sleep(Duration::from_millis(1000));
        let later = std::fs::metadata(&out)
            .expect("out")
            .modified()
            .expect("mtime");
        assert_eq!(settled, later, "rts watch keeps rendering without changes");
    });
    let _ = child.kill();
    let _ = child.wait();
    if let Err(e) = result {
        std::panic::resume_unwind(e);
    }
}
