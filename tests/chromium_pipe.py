"""One headless Chromium driven over the DevTools protocol on a pipe.

Chromium started with ``--remote-debugging-pipe`` reads commands on its file descriptor 3
and writes answers and events on 4, each a JSON message ended by a NUL byte. One browser
then prints many pages, a tab each, instead of one launch (about two seconds) a page.
No network and no package beyond the standard library.
"""

from __future__ import annotations

import base64
import contextlib
import json
import os
import select
import subprocess
import time
from pathlib import Path
from typing import Any

#: Flags of a quiet headless browser: with no network here, the background services
#: would only wait on it.
QUIET_FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
               "--no-first-run", "--disable-sync", "--disable-background-networking",
               "--disable-component-update")


class ChromiumError(RuntimeError):
    """The browser answered a command with an error, closed the pipe or timed out."""


class Chromium:
    """A headless Chromium and its DevTools pipe; use as a context manager."""

    def __init__(self, executable: str, profile: Path, timeout: float = 60.0) -> None:
        self.timeout = timeout
        self._next_id = 0
        self._buffer = b""
        self._events: list[dict[str, Any]] = []
        to_browser_read, self._to_browser = os.pipe()
        self._from_browser, from_browser_write = os.pipe()

        def give_the_pipe_fds_3_and_4() -> None:
            os.dup2(to_browser_read, 3)
            os.dup2(from_browser_write, 4)

        self._process = subprocess.Popen(
            [executable, *QUIET_FLAGS, "--remote-debugging-pipe",
             f"--user-data-dir={profile}", "about:blank"],
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            close_fds=False, preexec_fn=give_the_pipe_fds_3_and_4)  # noqa: PLW1509
        os.close(to_browser_read)
        os.close(from_browser_write)

    def __enter__(self) -> Chromium:
        return self

    def __exit__(self, *_: object) -> None:
        self.close()

    def close(self) -> None:
        if self._process.poll() is None:
            with contextlib.suppress(ChromiumError, OSError):
                self._send("Browser.close", {}, None)
            try:
                self._process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self._process.kill()
                self._process.wait()
        for fd in (self._to_browser, self._from_browser):
            with contextlib.suppress(OSError):
                os.close(fd)

    # --- the protocol --------------------------------------------------------------------

    def _send(self, method: str, params: dict[str, Any], session: str | None) -> int:
        self._next_id += 1
        message: dict[str, Any] = {"id": self._next_id, "method": method, "params": params}
        if session is not None:
            message["sessionId"] = session
        os.write(self._to_browser, json.dumps(message).encode() + b"\0")
        return self._next_id

    def _receive(self, deadline: float) -> dict[str, Any]:
        while b"\0" not in self._buffer:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self._from_browser], [], [], left)[0]:
                raise ChromiumError("no answer from the browser in time")
            chunk = os.read(self._from_browser, 1 << 20)
            if not chunk:
                raise ChromiumError("the browser closed its pipe")
            self._buffer += chunk
        message, self._buffer = self._buffer.split(b"\0", 1)
        return json.loads(message)

    def command(self, method: str, params: dict[str, Any] | None = None,
                session: str | None = None) -> dict[str, Any]:
        """Send a command and wait for its answer, keeping the events that come first."""
        wanted = self._send(method, params or {}, session)
        deadline = time.monotonic() + self.timeout
        while True:
            message = self._receive(deadline)
            if message.get("id") == wanted:
                if "error" in message:
                    raise ChromiumError(f"{method}: {message['error']}")
                return message.get("result", {})
            if "method" in message:
                self._events.append(message)

    def wait_for(self, method: str, session: str) -> dict[str, Any]:
        """The first event of that name from that tab, kept or still to come."""
        deadline = time.monotonic() + self.timeout
        while True:
            for event in self._events:
                if event["method"] == method and event.get("sessionId") == session:
                    self._events.remove(event)
                    return event
            message = self._receive(deadline)
            if "method" in message:
                self._events.append(message)

    # --- what the tests ask of it ------------------------------------------------------

    def print_page(self, url: str, width: int, height: int) -> tuple[bytes, bytes]:
        """The PDF a print of the page makes and a PNG screenshot of a window of
        width × height CSS pixels, from a tab of its own."""
        target = self.command("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = self.command("Target.attachToTarget",
                               {"targetId": target, "flatten": True})["sessionId"]
        try:
            self.command("Page.enable", session=session)
            self.command("Emulation.setDeviceMetricsOverride",
                         {"width": width, "height": height, "deviceScaleFactor": 1,
                          "mobile": False}, session)
            self.command("Page.navigate", {"url": url}, session)
            self.wait_for("Page.loadEventFired", session)
            pdf = self.command("Page.printToPDF", {}, session)["data"]
            png = self.command("Page.captureScreenshot", {"format": "png"}, session)["data"]
        finally:
            self.command("Target.closeTarget", {"targetId": target})
        return base64.b64decode(pdf), base64.b64decode(png)
