#!/usr/bin/env bash
# Render a gearwear HTML report in Debian's headless Chromium and check it in a real browser:
#   1. the page loads, and every <img> decodes: naturalWidth, naturalHeight > 0, and its
#      bottom pixel row is not fully transparent (Chromium shows a truncated PNG partially,
#      with the size from its header and transparent rows below the break; gearwear's plots
#      are drawn on an opaque white background, so a transparent last row means broken data);
#   2. no resource is refused by the page's Content-Security-Policy (a refused load would mean
#      the page tried to reach something outside itself);
#   3. a full-page screenshot is written for a human to look at.
# For developers and an opt-in CI step; not part of `cargo test` (installing Chromium is slow).
#
# Usage: tests/browser_check.sh REPORT.html [SCREENSHOT.png]
#   A sample page: `cargo test --test report_html` writes target/tmp/report.html.
#   SCREENSHOT defaults to REPORT with .png in place of .html.
#   Chromium is installed with apt-get if missing (set GEARWEAR_NO_INSTALL=1 to refuse).
# Exit status: 0 all images decode and nothing was refused; 1 a check failed; 2 usage/setup.

set -euo pipefail

die() { echo "browser_check: $*" >&2; exit 2; }
fail() { echo "browser_check: FAIL: $*" >&2; exit 1; }

[ $# -ge 1 ] && [ $# -le 2 ] || die "usage: $0 REPORT.html [SCREENSHOT.png]"
[ -f "$1" ] || die "no such file: $1"
report=$(realpath "$1")
shot=$(realpath -m "${2:-${report%.html}.png}")

if ! command -v chromium >/dev/null 2>&1; then
    [ -z "${GEARWEAR_NO_INSTALL:-}" ] || die "chromium not found and GEARWEAR_NO_INSTALL is set"
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    echo "browser_check: installing chromium (apt-get; this takes a while)" >&2
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq chromium >/dev/null
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# file:// URL of an absolute path (percent-encode the characters that break a URL).
file_url() {
    local p=$1
    p=${p//%/%25}; p=${p// /%20}; p=${p//#/%23}; p=${p//\?/%3F}
    printf 'file://%s' "$p"
}

# Chromium with a throw-away profile and nothing running in the background; the flags keep
# it from contacting any server on its own.
browser() {
    local profile
    profile=$(mktemp -d "$work/profile.XXXXXX")
    timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
        --disable-background-networking --disable-component-update --disable-sync \
        --disable-default-apps --disable-extensions --hide-scrollbars --mute-audio \
        --user-data-dir="$profile" "$@"
}

# The probe goes right after <head>, i.e. before the page's CSP <meta>: a meta policy only
# governs what follows it, so the probe runs while the page itself stays under its own
# policy, exactly as shipped. It records CSP refusals from the start and, on load, writes
# one line per image into <pre id="imgcheck">.
cat >"$work/probe.html" <<'EOF'
<script>
(function () {
  var refused = [];
  // Pixels with alpha > 0 in the image's bottom row (0 if unreadable).
  function lastRowOpaque(im) {
    try {
      var c = document.createElement('canvas');
      c.width = im.naturalWidth; c.height = im.naturalHeight;
      var g = c.getContext('2d');
      g.drawImage(im, 0, 0);
      var d = g.getImageData(0, c.height - 1, c.width, 1).data, n = 0;
      for (var k = 3; k < d.length; k += 4) { if (d[k] > 0) { n++; } }
      return n;
    } catch (e) { return 0; }
  }
  document.addEventListener('securitypolicyviolation', function (e) {
    refused.push('refused ' + e.effectiveDirective + ' ' + e.blockedURI);
  });
  window.addEventListener('load', function () {
    var imgs = document.images, ok = 0, lines = [];
    for (var i = 0; i < imgs.length; i++) {
      var im = imgs[i];
      var good = im.complete && im.naturalWidth > 0 && im.naturalHeight > 0;
      var last = good ? lastRowOpaque(im) : 0;
      good = good && last > 0;
      if (good) { ok++; }
      lines.push('img ' + i + ' ' + (good ? 'ok' : 'FAIL') + ' ' + im.naturalWidth + 'x'
                 + im.naturalHeight + ', opaque pixels in last row: ' + last);
    }
    var pre = document.createElement('pre');
    pre.id = 'imgcheck';
    pre.textContent = 'IMGCHECK images=' + imgs.length + ' ok=' + ok + ' refused='
      + refused.length + '\n' + lines.concat(refused).join('\n') + '\nIMGCHECK-END';
    document.body.appendChild(pre);
  });
})();
</script>
EOF
grep -q '<head>' "$report" || fail "no <head> line in $report"
sed "/<head>/r $work/probe.html" "$report" >"$work/check.html"

expected=$(grep -o '<img ' "$report" | wc -l)

# Virtual time lets the load event fire before the DOM is dumped.
if ! browser --run-all-compositor-stages-before-draw --virtual-time-budget=5000 \
    --dump-dom "$(file_url "$work/check.html")" >"$work/dom.html" 2>"$work/dom.log"; then
    cat "$work/dom.log" >&2
    fail "chromium could not load the page"
fi
# The dump also holds the probe's own source; the numbers mark its output.
result=$(sed -n '/IMGCHECK images=[0-9]/,/^IMGCHECK-END/p' "$work/dom.html" | sed 's/^.*IMGCHECK images=/IMGCHECK images=/')
[ -n "$result" ] || { cat "$work/dom.log" >&2; fail "page did not finish loading (no probe output)"; }
echo "$result" | sed '$d'

summary=$(echo "$result" | head -n 1)
images=$(echo "$summary" | sed -E 's/.*images=([0-9]+).*/\1/')
ok=$(echo "$summary" | sed -E 's/.* ok=([0-9]+).*/\1/')
refused=$(echo "$summary" | sed -E 's/.*refused=([0-9]+).*/\1/')

problems=()
[ "$images" -eq "$expected" ] || problems+=("browser saw $images images, the file has $expected")
[ "$ok" -eq "$images" ] || problems+=("$((images - ok)) of $images images did not decode")
[ "$refused" -eq 0 ] || problems+=("$refused resource load(s) refused by the page's CSP")
[ ${#problems[@]} -eq 0 ] || fail "$(IFS=';'; echo "${problems[*]}")"

# Screenshot of the page as shipped (no probe).
rm -f "$shot"
if ! browser --window-size=1200,3000 --screenshot="$shot" "$(file_url "$report")" \
    >"$work/shot.log" 2>&1; then
    cat "$work/shot.log" >&2
    fail "chromium could not take the screenshot"
fi
signature=$(head -c 8 "$shot" 2>/dev/null | od -An -tx1 | tr -d ' \n')
[ "$signature" = "89504e470d0a1a0a" ] || fail "no PNG screenshot written to $shot"

echo "browser_check: OK: $images/$images images decode, nothing refused; screenshot $shot"
