"""frictrack.report and Run.report_html: the same HTML file as `frictrack report`, made from the run folder, with
the Python call recorded as the command; a folder without results and a run without a folder are refused by name."""

import subprocess

import pytest

import frictrack
from test_run import cli


def test_a_run_reports_itself_as_the_command_line_reports_its_folder(tmp_path):
    run = frictrack.run(speed=120.0, devices=5, device_force=2e4, out=tmp_path / "run", progress=False)
    html = run.report_html()
    assert html.startswith("<!DOCTYPE html>") and "<svg " in html
    assert "frictrack.run(speed=120.0, devices=5, device_force=20000.0, out=" in html
    written = frictrack.report(tmp_path / "run")
    assert written == tmp_path / "run" / "report.html"
    by_command = subprocess.run([cli(), "report", str(tmp_path / "run"), "--out", str(tmp_path / "cli.html")],
                                capture_output=True, text=True)
    assert by_command.returncode == 0, by_command.stderr
    # The same page but for the footer's "written" instant.
    strip = lambda page: page[: page.index("<footer>")]
    assert strip(written.read_text()) == strip((tmp_path / "cli.html").read_text()) == strip(html)
    run.report_html(out=tmp_path / "copy.html")
    assert strip((tmp_path / "copy.html").read_text()) == strip(html)


def test_no_folder_no_report(tmp_path):
    with pytest.raises(frictrack.InputError, match="out=DIR"):
        frictrack.run(elements=50, progress=False).report_html()
    with pytest.raises(frictrack.InputError, match=f"invalid DIR = {tmp_path}: has no summary.json"):
        frictrack.report(tmp_path)
