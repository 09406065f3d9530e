#!/usr/bin/python3
"""The annotation page of `curvebench annotate` in headless Chromium, clicked as a person would.

A pentagon's 5 points clicked in order and closed save as the 5-cycle; one undo saves the
4-edge path; `evaluate`, `measure` and a benchmark input (`make-input`, as `run` makes its
inputs) accept the saved file through a `truth:` curve; the
page warns about points no curve visits and about a vertex of degree 3, and logs no console
error. Then a 10^4-point sample with its ground truth loaded measures how fast the page
answers, and a glyph with part of its ground truth gives the screenshot.

Usage: annotate_test.py PATH/TO/curvebench WORKDIR   (WORKDIR gets annotate.png and the files)
"""
import json
import math
import pathlib
import shutil
import subprocess
import sys
import time

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By

import chromium

PENTAGON_CYCLE = "0 1\n0 4\n1 2\n2 3\n3 4\n"
PENTAGON_PATH = "0 1\n1 2\n2 3\n3 4\n"


def curvebench(*args):
    return subprocess.run([CURVEBENCH, *map(str, args)], check=True, capture_output=True, text=True).stdout


def open_page(driver, points, edges=None, out=None):
    args = ["annotate", "-i", points, "-o", out or WORK / "pages"] + (["-e", edges] if edges else [])
    page = pathlib.Path(curvebench(*args).strip())
    driver.get(page.resolve().as_uri())
    chromium.wait_until(lambda: driver.execute_script("return !!window.curvebenchAnnotate"), "the page's script")


def move_to_point(driver, i):
    """Actions that put the mouse where point i is drawn (W3C offsets are from the canvas centre)."""
    canvas = driver.find_element(By.ID, "canvas")
    at = driver.execute_script("return window.curvebenchAnnotate.screenOf(arguments[0])", i)
    size = canvas.size
    return ActionChains(driver).move_to_element_with_offset(
        canvas, round(at["x"] - size["width"] / 2), round(at["y"] - size["height"] / 2))


def click_point(driver, i):
    move_to_point(driver, i).click().perform()


def save(driver, name):
    """Clicks Save and returns the downloaded file's text (an earlier download is removed first)."""
    target = DOWNLOADS / name
    target.unlink(missing_ok=True)
    driver.find_element(By.ID, "save").click()
    return chromium.wait_for_file(target)


def status(driver):
    return driver.find_element(By.ID, "status").text


def check(what, condition, detail=""):
    print(("ok: " if condition else "FAILED: ") + what + (f" ({detail})" if detail and not condition else ""))
    FAILURES.extend([] if condition else [what])


def pentagon(driver):
    points = WORK / "pentagon.xy"
    points.write_text("".join(f"{math.cos(2 * math.pi * k / 5):.6f} {math.sin(2 * math.pi * k / 5):.6f}\n"
                              for k in range(5)))
    open_page(driver, points)
    check("before drawing: 5 points no curve visits", "5 points no curve visits" in status(driver), status(driver))
    for i in range(5):
        click_point(driver, i)
    driver.find_element(By.ID, "close").click()
    cycle = save(driver, "pentagon.edges")
    check("clicked in order and closed: the 5-cycle", cycle == PENTAGON_CYCLE, repr(cycle))
    check("no warning on the closed pentagon", "⚠" not in status(driver), status(driver))
    shutil.copyfile(DOWNLOADS / "pentagon.edges", WORK / "pentagon-cycle.edges")

    driver.find_element(By.ID, "undo").click()
    path = save(driver, "pentagon.edges")
    check("one undo: the 4-edge path", path == PENTAGON_PATH, repr(path))

    cycle_file = WORK / "pentagon-cycle.edges"
    evaluation = json.loads(curvebench("evaluate", "-i", points, "-e", cycle_file, "-g", cycle_file))
    check("evaluate accepts the saved cycle (exact against itself)", evaluation["exact"] is True
          and evaluation["closed_components"] == 1, evaluation)
    measure = json.loads(curvebench("measure", "--curve", f"truth:{points}:{cycle_file}", "-i", points, "-e", cycle_file))
    check("measure accepts it as a truth: curve", measure["points"] == 5, measure)
    made = curvebench("make-input", f"truth:{points}:{cycle_file}|uniform=50", "-o", WORK / "resampled")
    check("a benchmark input (as `run` reads them) samples it as a truth: curve", "50 ground-truth edges" in made, made)
    path_eval = json.loads(curvebench("evaluate", "-i", points, "-e", DOWNLOADS / "pentagon.edges", "-g", cycle_file))
    check("the path is one open curve, not exact", path_eval["open_components"] == 1 and not path_eval["exact"],
          path_eval)

    # Undo restored the polyline being drawn; end it, then a chord from 0 to 2 gives point 2 degree 3.
    driver.find_element(By.ID, "end").click()
    click_point(driver, 0)
    click_point(driver, 2)
    check("degree 3 is warned about", "1 vertices of degree > 2: 2" in status(driver), status(driver))
    # Clicking the chord's middle (far from every point) deletes it.
    canvas = driver.find_element(By.ID, "canvas")
    a, b = (driver.execute_script("return window.curvebenchAnnotate.screenOf(arguments[0])", i) for i in (0, 2))
    ActionChains(driver).move_to_element_with_offset(
        canvas, round((a["x"] + b["x"]) / 2 - canvas.size["width"] / 2),
        round((a["y"] + b["y"]) / 2 - canvas.size["height"] / 2)).click().perform()
    check("clicking an edge deletes it", save(driver, "pentagon.edges") == PENTAGON_PATH and "⚠" not in status(driver),
          status(driver))
    errors = chromium.console_errors(driver)
    check("no console errors", not errors, errors)


def large_input(driver):
    """10^4 points with their ground truth: load time, and the time of 50 hovers and a zoom, each drawn."""
    base = WORK / "circle10k"
    curvebench("sample", "--curve", "ellipse:a=2,b=1", "--uniform", 10000, "-o", base)
    start = time.monotonic()
    open_page(driver, base.with_suffix(".xy"), base.with_suffix(".edges"))
    load = time.monotonic() - start
    timing = driver.execute_async_script("""
      const done = arguments[arguments.length - 1], canvas = document.getElementById('canvas');
      const r = canvas.getBoundingClientRect(), t0 = performance.now();
      for (let k = 0; k < 50; ++k)
        canvas.dispatchEvent(new MouseEvent('mousemove', {clientX: r.left + 10 * k, clientY: r.top + r.height / 2, bubbles: true}));
      requestAnimationFrame(() => {
        const t1 = performance.now();
        canvas.dispatchEvent(new WheelEvent('wheel', {deltaY: -100, clientX: r.left + r.width / 2, clientY: r.top + r.height / 2, bubbles: true}));
        requestAnimationFrame(() => requestAnimationFrame(() => done([t1 - t0, performance.now() - t1])));
      });""")
    print(f"10^4 points: page loaded in {load:.2f} s, 50 hovers + a frame {timing[0]:.0f} ms, "
          f"a zoom drawn in {timing[1]:.0f} ms")
    # Printed, not asserted: a timed check fails on a loaded machine (CI ran it at 280 ms).
    check("10^4 points, all visited: no warning", "⚠" not in status(driver), status(driver))


def screenshot(driver):
    """A glyph with two thirds of its ground truth: the rest is orange; a few edges drawn into it, the mouse on a point."""
    base = WORK / "glyph"
    curvebench("sample", "--curve", "glyph:g", "--epsilon", 0.3, "--safe", "-o", base)
    truth = base.with_suffix(".edges").read_text().splitlines()
    partial = WORK / "glyph-partial.edges"
    partial.write_text("\n".join(truth[: 2 * len(truth) // 3]) + "\n")
    open_page(driver, base.with_suffix(".xy"), partial)
    visited = {int(k) for line in truth[: 2 * len(truth) // 3] for k in line.split()}
    unvisited = [i for i in range(len(base.with_suffix(".xy").read_text().splitlines())) if i not in visited]
    for i in unvisited[:8:2]:  # a few edges drawn into the unvisited part, the mouse on the next point
        click_point(driver, i)
    move_to_point(driver, unvisited[10]).perform()
    driver.save_screenshot(str(WORK / "annotate.png"))
    check("screenshot written", (WORK / "annotate.png").stat().st_size > 0)
    check("the partial truth is warned about", "points no curve visits" in status(driver), status(driver))
    errors = chromium.console_errors(driver)
    check("no console errors on the larger pages", not errors, errors)


def main():
    global CURVEBENCH, WORK, DOWNLOADS, FAILURES
    CURVEBENCH, WORK = sys.argv[1], pathlib.Path(sys.argv[2]).resolve()
    DOWNLOADS, FAILURES = WORK / "downloads", []
    shutil.rmtree(WORK / "pages", ignore_errors=True)
    DOWNLOADS.mkdir(parents=True, exist_ok=True)
    driver = chromium.start(DOWNLOADS, width=1000, height=700)
    try:
        pentagon(driver)
        large_input(driver)
        screenshot(driver)
    finally:
        driver.quit()
    chromium.finish(FAILURES)


if __name__ == "__main__":
    main()
