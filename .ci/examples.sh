#!/usr/bin/env bash
# Runs every windowed example for real under Xvfb with software Vulkan and Bevy's
# `bevy_ci_testing` (a screenshot partway, another at exit, per .ci/examples/NAME.ron), then
# checks that each screenshot shows the scene and that the two differ (it animates).
#
# usage: .ci/examples.sh [--save DIR]   (--save copies each example's last screenshot to
#                                        DIR/NAME.png, e.g. assets/screenshots for the README)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
binaries="${CARGO_TARGET_DIR:-$root/target}/debug/examples"
save=""
if [ "${1:-}" = "--save" ]; then save=$(realpath -m "$2"); mkdir -p "$save"; fi

cargo build --examples --features bevy_ci_testing

failed=0
for source in examples/*.rs; do
    name=$(basename "$source" .rs)
    config="$root/.ci/examples/$name.ron"
    if [ "$name" = trajectory ]; then
        # The core example prints a table; it has no window.
        "$binaries/$name" > /dev/null
        echo "$name: ran"
        continue
    fi
    if [ ! -f "$config" ]; then
        echo "$name: no .ci/examples/$name.ron: every windowed example must be run in CI" >&2
        failed=1
        continue
    fi
    out="$root/.ci/out/$name"
    rm -rf "$out" && mkdir -p "$out"
    start=$(date +%s)
    # Examples load from the workspace's assets/ (cargo run sets this; a bare binary does not).
    if ! (cd "$out" && BEVY_ASSET_ROOT="$root" CI_TESTING_CONFIG="$config" timeout 900 \
            xvfb-run -a -s "-screen 0 1280x800x24" "$binaries/$name" \
            > run.log 2>&1); then
        echo "$name: FAILED to run (log: .ci/out/$name/run.log)" >&2
        tail -n 20 "$out/run.log" >&2
        failed=1
        continue
    fi
    shots=$(cd "$out" && ls screenshot-*.png 2>/dev/null | sort -t- -k2 -n || true)
    first=$(echo "$shots" | head -n 1)
    last=$(echo "$shots" | tail -n 1)
    if [ -z "$first" ] || [ "$first" = "$last" ]; then
        echo "$name: expected two screenshots, got: $shots" >&2
        failed=1
        continue
    fi
    echo "$name: ran in $(( $(date +%s) - start )) s"
    if ! python3 "$root/.ci/check_screenshots.py" "$name" "$out/$first" "$out/$last"; then
        failed=1
        continue
    fi
    if [ -n "$save" ]; then cp "$out/$last" "$save/$name.png"; fi
done
exit $failed
