#!/usr/bin/env bash
# The 3D plan viewer in a real browser: pages written by the demo for a disc plan and a Panda Cage 8 plan are opened
# in headless Chromium with no network (a namespace without interfaces where the machine allows one, and no proxy),
# and must load without a JavaScript error, draw robot-coloured pixels, and draw the robots elsewhere when the time
# slider is moved (the page's "#t=" moves it and sends it an input event, as a drag does); each page must stay under 2 MB and load nothing from outside. Writes the Panda page's screenshot to
# OUT_DIR/viewer_panda_cage_8.png (the picture of docs/user-guide.md).
# Usage: viewer_test.sh BIN_DIR CHROMIUM OUT_DIR
set -u
bin=$1 chromium=$2 out=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

offline=()
if unshare -n true 2>/dev/null; then offline=(unshare -n); fi
browse() {  # browse URL ARGS...: run headless Chromium on the page, offline
    local url=$1
    shift
    local clock=(--virtual-time-budget=4000)
    [ -n "${BROWSE_REAL:-}" ] && clock=()
    timeout 120 "${offline[@]}" "$chromium" --headless --no-sandbox --no-proxy-server --use-angle=swiftshader \
        --enable-unsafe-swiftshader --user-data-dir="$tmp/profile" --window-size=1200,800 "${clock[@]}" "$@" "$url"
}

check_page() {  # check_page NAME PAGE MID_TIME
    local name=$1 page=$2 mid=$3
    local size
    size=$(stat -c %s "$page")
    [ "$size" -lt 2000000 ] || fail "$name: page is $size bytes (limit 2 MB)"
    if grep -Eq "(src|href)=[\"']?(https?:)?//" "$page"; then fail "$name: page loads something from outside"; fi
    # Played for 4 s of (virtual) time: every frame's errors are caught.
    browse "file://$page" --dump-dom >"$tmp/$name.dom" 2>"$tmp/$name.log" || fail "$name: chromium failed"
    grep -q 'data-ready="1"' "$tmp/$name.dom" || fail "$name: the page did not finish loading"
    if grep -q 'data-errors' "$tmp/$name.dom"; then
        fail "$name: JavaScript errors: $(sed -n 's/.*<pre id="errors">\([^<]*\).*/\1/p' "$tmp/$name.dom")"
    fi
    if grep -q "Uncaught" "$tmp/$name.log"; then fail "$name: $(grep -m1 Uncaught "$tmp/$name.log")"; fi
    grep -q 'data-frames="[1-9]' "$tmp/$name.dom" || fail "$name: no frame drawn"
    # Real time (no virtual clock): the load and 120 frames drawn at once.
    BROWSE_REAL=1 browse "file://$page#t=0&bench" --dump-dom >"$tmp/$name-bench.dom" 2>/dev/null
    echo "$name: $size bytes; $(sed -n 's/.*data-load-ms="\([0-9]*\)".*/ready \1 ms after the start of loading/p' \
        "$tmp/$name-bench.dom"), $(sed -n 's/.*data-bench-ms="\([0-9.]*\)".*/\1 ms a frame/p' "$tmp/$name-bench.dom") \
(headless Chromium, software GL on this machine's CPUs), of which posing the robots \
$(sed -n 's/.*data-pose-ms="\([0-9.]*\)".*/\1 ms/p' "$tmp/$name-bench.dom")"
    browse "file://$page#t=0" --screenshot="$tmp/$name-0.png" >/dev/null 2>&1 || fail "$name: no screenshot"
    browse "file://$page#t=$mid" --screenshot="$tmp/$name-1.png" >/dev/null 2>&1 || fail "$name: no screenshot"
    /usr/bin/python3 - "$tmp/$name-0.png" "$tmp/$name-1.png" <<'PY' || fail "$name: screenshots"
import sys
from PIL import Image, ImageChops
first, second = (Image.open(p).convert("RGB") for p in sys.argv[1:3])
# Robots are drawn in saturated palette colours; the background, the obstacles and the panel are grey or white.
# The panel (left, 300 wide) and the bar (bottom) hold coloured swatches and controls: left out.
def robot_pixels(image):
    w, h = image.size
    return sum(1 for y in range(0, h - 60, 2) for x in range(0, w, 2)
               if x >= 300 and max(image.getpixel((x, y))) - min(image.getpixel((x, y))) > 90)
counts = [robot_pixels(first), robot_pixels(second)]
box = ImageChops.difference(first.crop((300, 0, first.width, first.height - 60)),
                            second.crop((300, 0, second.width, second.height - 60))).getbbox()
print("robot-coloured pixels at the two times (every second pixel):", counts, "; moved:", box is not None)
sys.exit(0 if min(counts) > 50 and box is not None else 1)
PY
}

"$bin/ompl_parc_demo" --scenario mobile_cross --robots 16 --picture "$tmp/discs.html" >/dev/null 2>&1 ||
    fail "demo: disc plan"
check_page discs "$tmp/discs.html" 20
"$bin/ompl_parc_demo" --scenario panda_cage --robots 8 --picture "$tmp/panda.html" >/dev/null 2>&1 ||
    fail "demo: Panda Cage 8 plan"
check_page panda "$tmp/panda.html" 2
[ -f "$tmp/panda-1.png" ] && mkdir -p "$out" && cp "$tmp/panda-1.png" "$out/viewer_panda_cage_8.png"

if [ "$failures" -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "viewer pages: all checks passed"
