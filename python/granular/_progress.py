"""The progress bar long calls draw with progress=True (on stderr: a terminal or a notebook)."""
import sys
import time


class ProgressBar:
    """`label: 37/100 [#######·········] 37%  12.3/s  ETA 5 s`, redrawn in place (at most 10 times a second)."""

    def __init__(self, total, label, stream=None, width=24):
        self.total = max(int(total), 1)
        self.label = label
        self.stream = stream if stream is not None else sys.stderr
        self.width = width
        self.start = time.monotonic()
        self.last_draw = 0.0
        self.done = 0
        self.closed = False
        self._draw()

    def update(self, done):
        self.done = min(int(done), self.total)
        now = time.monotonic()
        if now - self.last_draw >= 0.1:
            self._draw()

    def close(self, complete=True):
        if self.closed:
            return
        self.closed = True
        self._draw(final=True, note="" if complete else "  (stopped)")

    def _draw(self, final=False, note=""):
        self.last_draw = time.monotonic()
        elapsed = self.last_draw - self.start
        filled = int(self.width * self.done / self.total)
        rate = self.done / elapsed if elapsed > 0 else 0.0
        if final:
            tail = f"{elapsed:.1f} s"
        elif rate > 0:
            tail = f"{rate:.3g}/s  ETA {(self.total - self.done) / rate:.0f} s"
        else:
            tail = ""
        line = (f"\r{self.label}: {self.done}/{self.total} [{'#' * filled}{'.' * (self.width - filled)}] "
                f"{100 * self.done / self.total:3.0f}%  {tail}{note}")
        try:
            self.stream.write(line + ("\n" if final else ""))
            self.stream.flush()
        except (OSError, ValueError):  # a closed or broken stream must not stop the computation
            pass
