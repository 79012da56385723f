"""A countdown shown in the page, ticking in the browser (no kernel message per second).

The kernel keeps the deadline that counts (:class:`Countdown` only shows it): a submission
after it is not graded, whether or not the page told the kernel that the time ran out.
"""
import time

__all__ = ["countdown"]

#: The front end: ticks once a second from the moment it is shown; when the time is up it sets
#: ``expired`` (the kernel ends the exam) and stops.
_ESM = r"""
function render({ model, el }) {
  const box = document.createElement("div");
  box.className = "course-countdown";
  box.style.cssText = "font: 600 15px/1.4 var(--jp-ui-font-family, sans-serif);" +
                      "padding: 2px 8px; border-radius: 4px; display: inline-block;";
  el.appendChild(box);
  let timer = null;
  const paint = () => {
    const left = Math.max(0, model.get("deadline") - Date.now() / 1000 - model.get("skew"));
    const m = Math.floor(left / 60), s = Math.floor(left % 60);
    box.textContent = model.get("stopped") ? model.get("final") :
      `Time left: ${m}:${String(s).padStart(2, "0")}`;
    box.style.background = left < 60 && !model.get("stopped") ? "#fde2e4" : "#eef2f7";
    if (left <= 0 && !model.get("stopped") && !model.get("expired")) {
      model.set("expired", true);
      model.save_changes();
    }
    if (model.get("stopped") || left <= 0) { clearInterval(timer); timer = null; }
  };
  const start = () => {
    if (timer === null && !model.get("stopped")) timer = setInterval(paint, 250);
    paint();
  };
  model.on("change:deadline", start);
  model.on("change:stopped", paint);
  start();
  return () => clearInterval(timer);
}
export default { render };
"""

_CLASS = None


def _countdown_class():
    global _CLASS
    if _CLASS is None:
        import anywidget
        import traitlets

        class Countdown(anywidget.AnyWidget):
            """The time left until ``deadline`` (seconds since the epoch, the kernel's clock)."""

            _esm = _ESM
            deadline = traitlets.Float(0.0).tag(sync=True)
            #: The page's clock minus the kernel's, when they differ (0: the same machine).
            skew = traitlets.Float(0.0).tag(sync=True)
            expired = traitlets.Bool(False).tag(sync=True)
            stopped = traitlets.Bool(False).tag(sync=True)
            final = traitlets.Unicode("").tag(sync=True)

            def left(self):
                """Seconds left by the kernel's clock (never negative)."""
                return max(0.0, self.deadline - time.time())

            def stop(self, text):
                """Stop ticking and show `text` instead."""
                self.final, self.stopped = text, True

        _CLASS = Countdown
    return _CLASS


def countdown(minutes):
    """A :class:`Countdown` of `minutes` from now.

    Examples
    --------
    >>> c = countdown(20)
    >>> 1199 < c.left() <= 1200, c.expired
    (True, False)
    """
    return _countdown_class()(deadline=time.time() + 60.0 * float(minutes))


def __getattr__(name):
    if name == "Countdown":
        return _countdown_class()
    raise AttributeError(name)
