"""check_run_page.py PAGE.html OUT_DIR [--max-bytes N] [--min-fps F] [--tries K]

The page of a replayed walk_forward (`wpg view`) in headless Chromium with the network off:
- opened at #t=0 and at #t=6 (the camera held still: follow=0), it logs no error, no warning,
  no exception, and requests nothing but its own file;
- it opens paused at the time of the fragment (the contract of `#t=SECONDS`);
- the NMPC preview shown is the plan of the iteration at the fragment's time (mpc/time holds
  0, 0.1, ... s: exactly t), with the steps it previewed (at least one while walking at 6 s);
- the two screenshots differ where the robot is (its box on the screen, which the page
  publishes) and not in a corner of the sky away from it: the robot walked, the view held;
- with --max-bytes, the page is at most that large;
- with --min-fps, playing it is measured (requestAnimationFrame counted by the page itself over
  3 s, after 1 s to settle its render scale) and the frames per second printed. A frame rate
  is a timing, which a shared machine does not give reliably: it is asserted (at least
  --min-fps, the best of --tries attempts) only when WPG_VIEWER_MEASURE_FPS=1 is in the
  environment (docs/viewer.md, "Measuring the frame rate"); otherwise it is measured once,
  over 1 s, and printed (the page still plays, and logs no error while it does).
Screenshots are kept in OUT_DIR (t0.png, t6.png). Exit 0, or 1 with the reasons.
"""
import argparse
import os
import sys

import numpy as np
from matplotlib import image

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from headless_page import HeadlessChromium  # noqa: E402

READY = "document.body && document.body.dataset.wpgReady === '1'"


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def box_of(text):
    x0, y0, x1, y1 = (float(v) for v in text.split(","))
    return int(max(0, x0)), int(max(0, y0)), int(x1) + 1, int(y1) + 1


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("page")
    parser.add_argument("out")
    parser.add_argument("--max-bytes", type=float)
    parser.add_argument("--min-fps", type=float)
    parser.add_argument("--tries", type=int, default=3)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    page_path = os.path.abspath(args.page)
    folder = "file://" + os.path.dirname(page_path) + "/"
    url = "file://" + page_path
    size = os.path.getsize(page_path)
    print("page %s: %.2f MB" % (page_path, size / 1e6))
    if args.max_bytes and size > args.max_bytes:
        fail("the page is %d bytes, more than %d" % (size, args.max_bytes))

    shots, boxes = {}, {}
    with HeadlessChromium() as browser:
        for t in (0, 6):
            page = browser.open(url + "#t=%d&follow=0" % t)
            page.wait_for(READY)
            shown = float(page.evaluate("document.body.dataset.wpgTime"))
            playing = page.evaluate("document.querySelector('button.play').classList.contains('playing')")
            if abs(shown - t) > 1e-3 or playing:
                fail("#t=%d: the page shows t = %s s, %s (expected paused at %d s)"
                     % (t, shown, "playing" if playing else "paused", t))
            preview = page.evaluate("document.body.dataset.wpgPreview")
            iteration, ghosts = (float(v) for v in preview.split(","))
            if abs(iteration - t) > 1e-4 or (t == 6 and ghosts == 0):
                fail("#t=%d: the preview shows the plan of t = %s s with %d ghost steps (expected "
                     "t = %d s%s)" % (t, iteration, ghosts, t, ", some" if t == 6 else ""))
            path = os.path.join(args.out, "t%d.png" % t)
            page.screenshot(path)
            shots[t] = image.imread(path)[:, :, :3]
            boxes[t] = box_of(page.evaluate("document.body.dataset.robotBox"))
            problems = page.problems(folder)
            if problems:
                fail("#t=%d: %s" % (t, "; ".join(problems)))
            print("#t=%d: paused at %.3f s, robot box %s, screenshot %s" % (t, shown, boxes[t], path))

        difference = np.abs(shots[6] - shots[0]).max(axis=2)
        for t, (x0, y0, x1, y1) in boxes.items():
            changed = float(np.mean(difference[y0:y1, x0:x1] > 0.02))
            print("robot box at t=%d: %.1f %% of its pixels changed" % (t, 100 * changed))
            if changed < 0.05:
                fail("the screenshots at t=0 and t=6 do not differ where the robot is at t=%d "
                     "(%.1f %% of the box)" % (t, 100 * changed))
        # The sky in the top right corner of the view, away from the robot: unchanged.
        x0 = max(boxes[0][2], boxes[6][2]) + 40
        sky = difference[60:140, x0:x0 + 120] if x0 + 120 < difference.shape[1] else None
        if sky is not None and sky.size and float(np.mean(sky > 0.02)) > 0.01:
            fail("the view moved: the sky away from the robot changed between t=0 and t=6")

        if args.min_fps:
            asserted = os.environ.get("WPG_VIEWER_MEASURE_FPS") == "1"
            best = 0.0
            for attempt in range(args.tries if asserted else 1):
                # 3 s when asserted; 1 s when only printed, half the rendering on the CPU.
                page = browser.open(url + "#t=0&measure=%d" % (3 if asserted else 1))
                page.wait_for("document.getElementById('wpg-fps') && "
                              "document.getElementById('wpg-fps').dataset.fps", timeout=120)
                fps = float(page.evaluate("document.getElementById('wpg-fps').dataset.fps"))
                scale = page.evaluate("document.getElementById('wpg-fps').dataset.scale")
                problems = page.problems(folder)
                if problems:
                    fail("playing: " + "; ".join(problems))
                print("playing: %.1f frames per second at render scale %s (attempt %d, load %s)"
                      % (fps, scale, attempt + 1, open("/proc/loadavg").read().split()[0]))
                best = max(best, fps)
                if best >= args.min_fps:
                    break
            if not asserted:
                print("frame rate: %.1f frames per second (measured, not asserted: "
                      "WPG_VIEWER_MEASURE_FPS=1 requires at least %.0f)" % (best, args.min_fps))
            elif best < args.min_fps:
                fail("%.1f frames per second at best, expected at least %.0f" % (best, args.min_fps))
            else:
                print("frame rate: %.1f frames per second, at least %.0f" % (best, args.min_fps))
    return 0


if __name__ == "__main__":
    sys.exit(main())
