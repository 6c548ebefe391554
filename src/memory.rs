//! The heap, counted. Every allocation of the process goes through a counting
//! allocator ([`cap::Cap`] over the system allocator), so evaluation can hold a
//! scene to its memory budget (`--max-memory`) by reading how much is live,
//! however the memory was taken: values, arrays, strings, objects, meshes,
//! decoded images.

#[global_allocator]
static HEAP: cap::Cap<std::alloc::System> = cap::Cap::new(std::alloc::System, usize::MAX);

/// Bytes of heap the process holds now.
pub fn heap_bytes() -> usize {
    HEAP.allocated()
}

/// The machine's physical memory in bytes, when it can be read (Linux:
/// `/proc/meminfo`).
pub fn physical_memory() -> Option<u64> {
    let info = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = info.lines().find(|l| l.starts_with("MemTotal:"))?;
    let kib: u64 = line
        .trim_start_matches("MemTotal:")
        .trim()
        .trim_end_matches("kB")
        .trim()
        .parse()
        .ok()?;
    Some(kib * 1024)
}

/// The default budget of one evaluation: half the machine's memory, at most
/// 8 GiB (8 GiB when the machine's memory is unknown), so a runaway scene
/// stops while the machine stays usable.
pub fn default_eval_budget() -> u64 {
    const CAP: u64 = 8 << 30;
    physical_memory().map_or(CAP, |m| (m / 2).min(CAP))
}

/// `bytes` for people, in the largest unit that keeps a whole number part
/// (`7 B`, `12 KiB`, `1.5 GiB`).
pub fn show_size(bytes: u64) -> String {
    const UNITS: [&str; 4] = ["KiB", "MiB", "GiB", "TiB"];
    if bytes < 1024 {
        return format!("{bytes} B");
    }
    let (mut v, mut unit) = (bytes as f64, "B");
    for u in UNITS {
        if v < 1024.0 {
            break;
        }
        v /= 1024.0;
        unit = u;
    }
    if v.fract() == 0.0 {
        format!("{v} {unit}")
    } else {
        format!("{v:.1} {unit}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_show_in_the_largest_unit() {
        assert_eq!(show_size(7), "7 B");
        assert_eq!(show_size(2 << 30), "2 GiB");
        assert_eq!(show_size(3 << 29), "1.5 GiB");
    }

    #[test]
    fn the_heap_counter_sees_an_allocation() {
        // Other tests allocate on other threads at the same time: look for an
        // increase of at least most of the block while it is held.
        let before = heap_bytes();
        let block = vec![1u8; 256 << 20];
        let during = heap_bytes();
        assert!(during >= before + (128 << 20), "{before} -> {during}");
        drop(block);
    }
}
