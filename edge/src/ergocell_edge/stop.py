"""Ctrl-C / SIGTERM: a flag the frame loops check between frames (a second signal stops at once)."""

from __future__ import annotations

import signal
import threading


class StopFlag:
    def __init__(self):
        self.event = threading.Event()
        self.signal_name: "str | None" = None
        self._previous = {}

    def __bool__(self) -> bool:
        return self.event.is_set()

    def set(self, name: str = "stop") -> None:
        self.signal_name = self.signal_name or name
        self.event.set()

    def sleep(self, seconds: float) -> bool:
        """Sleep unless stopped; True when stopped."""
        if seconds > 0:
            self.event.wait(seconds)
        return self.event.is_set()

    def _handler(self, signum, _frame):
        if self.event.is_set():
            # A second Ctrl-C: give up on the clean stop.
            raise KeyboardInterrupt
        self.set(signal.Signals(signum).name)

    def install(self) -> "StopFlag":
        for sig in (signal.SIGINT, signal.SIGTERM):
            self._previous[sig] = signal.signal(sig, self._handler)
        return self

    def restore(self) -> None:
        for sig, h in self._previous.items():
            signal.signal(sig, h)
        self._previous.clear()
