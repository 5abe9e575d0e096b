#!/usr/bin/env python3
"""gcsim report as a user opens it: a traced ray-tracing run with an image, its report, and a
screenshot of the first screen in headless Chromium. The page must lead with the answer (simulated
and wall time, the image) before the plots, fold the counters and configuration, and say how to open
each trace file; the screenshot must show something in its upper half.

  report_screenshot_test.py GCSIM WORKDIR     exit 77 (CTest: skipped) when chromium is absent,
                                              after the checks of the page itself"""

import os
import re
import shutil
import subprocess
import sys
import tempfile

SKIPPED = 77


def fail(message):
    print(f"report_screenshot_test: {message}", file=sys.stderr)
    sys.exit(1)


def run(cmd, cwd):
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=600)
    if proc.returncode != 0:
        fail(f"{' '.join(cmd)} exited {proc.returncode}:\n{proc.stdout}\n{proc.stderr}")
    return proc.stdout


def check_page(html):
    """Order of the page: headline (with the image) first, then the plots, then folded tables."""
    def at(needle):
        i = html.find(needle)
        if i < 0:
            fail(f"index.html lacks {needle!r}")
        return i
    headline, image, plots = at('class="headline"'), at('src="teapots.png"'), at('src="plots/gantt.png"')
    counters, config = at("<h2>Counters and configuration</h2>"), at("<summary><b>Configuration</b>")
    if not headline < image < plots < counters < config:
        fail("index.html is not in the order headline, image, plots, counters, configuration")
    if at("simulated time of the run") > plots or at("wall-clock time on the host") > plots:
        fail("the simulated and wall times are not in the headline")
    first_table = html.find("<table>")
    if first_table >= 0 and html.rfind("<details>", 0, first_table) < 0:
        fail("a table is shown before any folded <details>")
    for ext, how in ((".json", "perfetto"), (".paje", "ViTE"), (".csv", "gcsim plot")):
        if not re.search(rf'href="[^"]*t{re.escape(ext)}".*{how}', html, re.IGNORECASE):
            fail(f"no link to t{ext} with how to open it ({how})")
    if not re.search(r"busy [\d.]+&nbsp;%, communicating [\d.]+&nbsp;%, waiting [\d.]+&nbsp;%", html):
        fail("the headline does not give the busy / communicating / waiting shares")


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n":
        fail(f"{path} is not a PNG")
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")


def check_screenshot(path):
    width, height = png_size(path)
    if (width, height) != (1280, 900):
        fail(f"screenshot is {width}x{height}, expected 1280x900")
    try:
        import matplotlib.image
    except ImportError:
        return  # the size check stands alone without matplotlib
    pixels = matplotlib.image.imread(path)[..., :3]
    upper = pixels[: height // 2]
    inked = (upper.min(axis=2) < 0.9).mean()
    colourful = (upper.max(axis=2) - upper.min(axis=2) > 0.15).mean()
    if inked < 0.02 or colourful < 0.005:
        fail(f"the first screen's upper half looks empty ({inked:.1%} inked, {colourful:.1%} in colour)")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    gcsim, work = os.path.abspath(sys.argv[1]), sys.argv[2]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    run([gcsim, "run", "raytrace", "--scene", "teapots", "--nodes", "4", "--size", "128", "--image", "teapots.png",
         "--json", "r.json", "--trace", "t.json", "--trace-level", "messages"], work)
    run([gcsim, "report", "r.json", "--out", "rep"], work)
    with open(os.path.join(work, "rep", "index.html"), encoding="utf-8") as f:
        check_page(f.read())
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        print("the page's order checked; chromium is not installed (apt-get install chromium): screenshot skipped")
        return SKIPPED
    shot = os.path.join(work, "first_screen.png")
    with tempfile.TemporaryDirectory() as profile:
        subprocess.run([chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                        "--disable-component-update", "--disable-sync", "--no-first-run", f"--user-data-dir={profile}",
                        f"--screenshot={shot}", "--window-size=1280,900",
                        "file://" + os.path.abspath(os.path.join(work, "rep", "index.html"))],
                       capture_output=True, text=True, timeout=120)
    if not os.path.exists(shot):
        fail(f"chromium wrote no screenshot {shot}")
    check_screenshot(shot)
    print(f"report leads with the headline; first screen in {shot}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
