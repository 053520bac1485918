"""`frictrack report` in a real browser: a run folder's and a study folder's report load in headless Chromium with
no console error, every figure renders (an inline SVG with its curves, drawn at a readable size), the page is not
blank, and a screenshot of each is kept for a reader to look at (target/report-screenshots/).

Needs Debian's chromium and chromium-driver (``.ci/run`` installs them) and selenium (scripts/test installs it);
without them the tests are skipped, except under CI (``CI=true``), where a missing browser fails.
"""

import os
import re
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

import pytest

from test_run import ROOT, cli

SHOTS = ROOT / "target" / "report-screenshots"
# Debian's chromium and chromium-driver (what .ci/run installs), or a Chrome and its driver on PATH (a GitHub runner).
CHROMIUM = os.environ.get("CHROMIUM") or shutil.which("chromium") or shutil.which("google-chrome") or "/usr/bin/chromium"
DRIVER = os.environ.get("CHROMEDRIVER") or shutil.which("chromedriver") or "/usr/bin/chromedriver"


@pytest.fixture(scope="module")
def browser():
    """Headless Chromium driven by chromedriver, recording the console (Chromium's flags for a closed network)."""
    missing = [p for p in (CHROMIUM, DRIVER) if not Path(p).exists()]
    try:
        from selenium import webdriver
        from selenium.webdriver.chrome.service import Service
    except ImportError:
        missing.append("selenium")
    if missing:
        if os.environ.get("CI") == "true":
            pytest.fail(f"no {', '.join(missing)}: .ci/run installs chromium, chromium-driver and selenium")
        pytest.skip(f"no {', '.join(missing)} (apt-get install chromium chromium-driver; pip install selenium)")
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 "--window-size=1280,1600", f"--user-data-dir={tempfile.mkdtemp(prefix='frictrack-chromium-')}"):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(executable_path=DRIVER), options=options)
    yield driver
    driver.quit()


def console_errors(driver):
    """The console's errors (level SEVERE) since the last call."""
    return [entry["message"] for entry in driver.get_log("browser") if entry["level"] == "SEVERE"]


# Each figure: its box on the page (px), its curves (plotters draws a series as a polyline of many points, an axis
# or a tick as one of two) and its other marks.
FIGURES = """return Array.from(document.querySelectorAll('figure svg')).map(s => {
  const r = s.getBoundingClientRect();
  const curves = Array.from(s.querySelectorAll('polyline')).filter(p => p.points.numberOfItems > 10).length;
  return {width: r.width, height: r.height, curves: curves,
          marks: s.querySelectorAll('path, circle, line, text').length};
});"""


def check_page(driver, html: Path, figures: int, shot: str):
    """Load `html`, then: no console error, the title and contents drawn, `figures` figures each drawn with its
    curves at ≥ 400 px wide, a screenshot that is not blank."""
    driver.get(html.as_uri())
    assert console_errors(driver) == []
    assert driver.execute_script("return document.querySelector('h1').textContent").startswith("frictrack")
    assert driver.execute_script("return document.querySelectorAll('nav.toc a').length") >= 4
    drawn = driver.execute_script(FIGURES)
    assert len(drawn) == figures, drawn
    for f in drawn:
        # 400 px: a figure squeezed below that would be unreadable; a figure without a curve shows nothing; 20 marks:
        # a title, axis labels, ticks and their numbers.
        assert f["width"] >= 400 and f["height"] >= 250 and f["curves"] >= 1 and f["marks"] >= 20, f
    SHOTS.mkdir(parents=True, exist_ok=True)
    # The whole page: the window as tall as the document.
    height = driver.execute_script("return document.documentElement.scrollHeight")
    driver.set_window_size(1280, min(height, 16000))
    path = SHOTS / f"{shot}.png"
    driver.save_screenshot(str(path))
    import numpy as np
    from PIL import Image

    inked = float(np.mean(np.asarray(Image.open(path).convert("L")) < 200))
    # A blank page has no ink; text, tables and figures cover a few percent of it.
    assert inked > 0.01, f"{path}: {inked:.4f} of the page inked"
    driver.set_window_size(1280, 1600)


def report(folder: Path) -> Path:
    """`frictrack report FOLDER`: the HTML file it wrote."""
    out = subprocess.run([cli(), "report", str(folder)], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return folder / "report.html"


def test_a_run_report_renders_in_chromium(browser, tmp_path):
    folder = tmp_path / "run"
    out = subprocess.run([cli(), "run", "--speed", "150", "--distributed-friction", "2000", "--out", str(folder),
                          "--quiet"], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    svgs = len(list(folder.glob("*.svg")))
    check_page(browser, report(folder), svgs, "run")


def test_a_study_report_renders_in_chromium(browser, tmp_path):
    folder = tmp_path / "study"
    out = subprocess.run([cli(), "study", "receptance", "--out", str(folder), "--quiet"], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    check_page(browser, report(folder), len(list(folder.glob("*.svg"))), "study")


def test_the_check_sees_a_console_error_and_a_missing_figure(browser, tmp_path):
    """The checks can fail: a page that logs an error, and a report whose figure lost its curves."""
    broken = tmp_path / "broken.html"
    broken.write_text("<!DOCTYPE html><html><body><h1>x</h1><script>console.error('boom')</script></body></html>")
    browser.get(broken.as_uri())
    logged = console_errors(browser)
    for _ in range(20):  # the log may arrive a moment after the page
        if logged:
            break
        time.sleep(0.1)
        logged = console_errors(browser)
    assert any("boom" in e for e in logged), logged
    folder = tmp_path / "run"
    subprocess.run([cli(), "run", "--out", str(folder), "--quiet"], check=True, capture_output=True)
    figure = folder / "histories-deflection.svg"
    text = figure.read_text()
    # The figure's curves lost: every polyline removed.
    figure.write_text(re.sub(r"<polyline[^>]*/>", "", text))
    browser.get(report(folder).as_uri())
    drawn = browser.execute_script(FIGURES)
    assert [f["curves"] for f in drawn].count(0) == 1, drawn
    shutil.rmtree(folder)
