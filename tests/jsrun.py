"""Run JavaScript for the tests: with ``node`` when installed, else in headless Chromium.

``run_js(source)`` evaluates ``source`` (a program whose last statement is an
expression) and returns that expression's value through JSON.  Tests skip when
neither node nor Chromium (with websocket-client) is present.
"""

from __future__ import annotations

import json
import shutil
import subprocess
from typing import Any

import pytest
from cdp import Browser, browser_or_skip

_BROWSER: list[Browser] = []


def run_js(source: str) -> Any:
    """The JSON value of the program's final expression ``RESULT`` (the source must set it)."""
    node = shutil.which("node") or shutil.which("nodejs")
    if node is not None:
        # the program on standard input: an argument is limited to 128 KiB (MAX_ARG_STRLEN),
        # which a page's whole script with a six-bar's forces passes
        program = source + "\nprocess.stdout.write(JSON.stringify(RESULT));"
        r = subprocess.run([node, "-"], input=program, capture_output=True, text=True,
                           timeout=60, check=False)
        if r.returncode != 0:
            raise RuntimeError(r.stderr[-2000:])
        return json.loads(r.stdout)
    if not _BROWSER:
        _BROWSER.append(browser_or_skip())
    b = _BROWSER[0]
    return json.loads(b.js(f"(function () {{ {source}\n return JSON.stringify(RESULT); }})()"))


def close() -> None:
    """End the browser started here, if any."""
    while _BROWSER:
        _BROWSER.pop().close()


def js_or_skip() -> None:
    """Skip unless node or Chromium can run JavaScript."""
    from cdp import chromium

    if shutil.which("node") or shutil.which("nodejs"):
        return
    if chromium() is None:
        pytest.skip("neither node nor chromium is installed")
