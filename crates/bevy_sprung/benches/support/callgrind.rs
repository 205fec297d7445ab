//! Instruction counts under `valgrind --tool=callgrind`, for the benches that report them.

use std::process::Command;

/// The instructions counted in `function` (a callgrind pattern, on the thread that calls it)
/// when this binary runs with `args` under callgrind, with `compute_threads` in the compute
/// pool (`None`: Bevy's default).
pub(crate) fn callgrind(function: &str, compute_threads: Option<usize>, args: &[&str]) -> u64 {
    let exe = std::env::current_exe().expect("the bench binary");
    let out = std::env::temp_dir().join(format!("callgrind.sprung.{}", args.join(".")));
    let mut command = Command::new("valgrind");
    if let Some(threads) = compute_threads {
        command.env("SPRUNG_BENCH_COMPUTE_THREADS", threads.to_string());
    }
    let status = command
        .arg("--tool=callgrind")
        .arg("--collect-atstart=no")
        .arg(format!("--toggle-collect={function}"))
        .arg(format!("--callgrind-out-file={}", out.display()))
        .arg(&exe)
        .args(args)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status()
        .expect("valgrind runs (install it: apt-get install valgrind)");
    assert!(status.success(), "callgrind failed for {args:?}");
    let text = std::fs::read_to_string(&out).expect("callgrind output");
    let _removed = std::fs::remove_file(&out);
    text.lines()
        .find_map(|line| line.strip_prefix("summary: "))
        .and_then(|total| total.trim().parse().ok())
        .expect("a summary line")
}
