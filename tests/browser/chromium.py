"""Headless Chromium for the browser tests, through Debian's python3-selenium and chromium-driver.

As root (CI) Chromium needs --no-sandbox; /dev/shm is small in containers, hence
--disable-dev-shm-usage. Downloads go to a given directory, and the browser console is
kept so that a test can fail on any error the page logged.
"""
import pathlib
import sys
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

CHROMEDRIVER = "/usr/bin/chromedriver"
CHROMIUM = "/usr/bin/chromium"


def start(download_dir, width=1400, height=900):
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                 "--no-first-run", f"--window-size={width},{height}"):
        options.add_argument(flag)
    options.add_experimental_option("prefs", {"download.default_directory": str(download_dir),
                                              "download.prompt_for_download": False})
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)
    # Headless Chromium only downloads where this says (the preference alone is not enough).
    driver.execute_cdp_cmd("Page.setDownloadBehavior", {"behavior": "allow", "downloadPath": str(download_dir)})
    return driver


def console_errors(driver):
    """Console entries of level SEVERE since the last call (reading the log empties it)."""
    return [e["message"] for e in driver.get_log("browser") if e["level"] == "SEVERE"]


def wait_for_file(path, seconds=10):
    """The text of a downloaded file once Chromium has finished writing it."""
    path = pathlib.Path(path)
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        partial = list(path.parent.glob("*.crdownload"))
        if path.is_file() and not partial:
            return path.read_text()
        time.sleep(0.05)
    raise AssertionError(f"no download {path} within {seconds} s")


def wait_until(condition, what, seconds=10):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        value = condition()
        if value:
            return value
        time.sleep(0.05)
    raise AssertionError(f"timed out waiting for {what}")


def finish(failures):
    """The closing line every shell test prints, and the exit status: 0 if nothing failed."""
    print(f"{'0' if failures else '1'} passed, {len(failures)} failed")
    sys.exit(1 if failures else 0)
