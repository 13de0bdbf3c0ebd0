"""How long calls run: on a thread of their own, with the progress bar they draw with progress=True (on stderr: a
terminal or a notebook) and a clean stop on Ctrl-C."""
import sys
import threading
import time


def run_long(work, done, cancel, label, total, progress, interrupted="interrupted (Ctrl-C)"):
    """Runs work() (a _core call that releases the GIL) on a thread of its own while this (calling) thread waits in
    50 ms steps, so Ctrl-C reaches it, and draws a ProgressBar of done() out of `total` when `progress`. On
    KeyboardInterrupt it calls cancel(), waits for work() to stop (the library finishes and checkpoints the
    realizations in flight) and raises a KeyboardInterrupt saying `interrupted` (the call that continues the run); an
    exception of work() is raised here. (The C++
    caller waits for work() too, whatever happens here: Python 3.11's Thread.join can return early when
    interrupted.)"""
    bar = ProgressBar(total, label) if progress else None
    failure = []

    def target():
        try:
            work()
        except BaseException as error:  # noqa: B036 (raised again on the calling thread)
            failure.append(error)

    worker = threading.Thread(target=target, name=f"granular {label}", daemon=True)
    worker.start()
    try:
        while worker.is_alive():
            worker.join(0.05)
            if bar is not None:
                bar.update(done())
    except BaseException as error:
        cancel()  # whatever happened here, the worker is told to stop and waited for
        worker.join()
        if bar is not None:
            try:
                bar.close(False)
            except Exception:  # noqa: S110 (the first exception is the one to report)
                pass
        if isinstance(error, KeyboardInterrupt) and not error.args:  # Ctrl-C's own says nothing
            raise KeyboardInterrupt(interrupted) from None
        raise
    if bar is not None:
        bar.update(done())
        bar.close(not failure)
    if failure:
        raise failure[0]


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
