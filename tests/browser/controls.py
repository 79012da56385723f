"""Drive every control of a widget view as a student would, and watch its picture.

The controls are found in the page, not in the kernel: every slider, menu, toggle, button,
check box, text field and colour picker inside a widget view (matplotlib's own toolbar is not an
explorer control and is left alone). Each is given a stable key (kind, label, occurrence) so a
control that a previous action re-created (the composer's rows) is still recognised, and each
is operated with the keyboard or the mouse. The mouse gestures of the figure come from the
kernel (:meth:`course_lib.widgets._base.Explorer.mouse_gestures`).
"""
import re
import time

from .lab import drag_on_canvas

# A control inside a view; toggle buttons of a ToggleButtons group are one control.
_ENUMERATE = r"""(root) => {
  const out = [];
  const seen = {};
  const label = (el) => {
    const l = el.querySelector(':scope > .widget-label');
    return l ? l.textContent.trim() : '';
  };
  const title = (el) => {
    const t = el.getAttribute('title');
    return t && t !== 'null' ? t : el.textContent.trim();
  };
  const selector = ['.widget-slider', '.widget-dropdown', '.widget-toggle-buttons',
                    'button.widget-button', 'button.widget-toggle-button', '.widget-checkbox',
                    '.widget-text', '.widget-textarea', '.widget-colorpicker'].join(', ');
  root.querySelectorAll('[data-course-control]').forEach(e => e.removeAttribute('data-course-control'));
  root.querySelectorAll(selector).forEach(el => {
    if (el.closest('.jupyter-matplotlib-toolbar')) return;
    if (el.matches('button.widget-toggle-button') && el.closest('.widget-toggle-buttons')) return;
    let kind, name, disabled = false, options = null, selected = null;
    if (el.matches('.widget-slider')) {
      kind = 'slider'; name = label(el);
      disabled = !!el.querySelector('.noUi-target[disabled]');
    } else if (el.matches('.widget-dropdown')) {
      const select = el.querySelector('select');
      kind = 'menu'; name = label(el); disabled = select.disabled;
      options = [...select.options].map(o => o.textContent.trim().replace(/\u00a0/g, ' '));
      selected = select.selectedIndex;
    } else if (el.matches('.widget-toggle-buttons')) {
      const buttons = [...el.querySelectorAll('button')];
      kind = 'toggles'; name = label(el) || buttons.map(b => b.textContent.trim()).join('/');
      disabled = buttons.every(b => b.disabled);
      options = buttons.map(b => b.textContent.trim().replace(/\u00a0/g, ' '));
      selected = buttons.findIndex(b => b.classList.contains('mod-active'));
    } else if (el.matches('button.widget-button')) {
      kind = 'button'; name = title(el);
      disabled = el.disabled;
    } else if (el.matches('button.widget-toggle-button')) {
      kind = 'toggle'; name = title(el);
      disabled = el.disabled;
    } else if (el.matches('.widget-checkbox')) {
      kind = 'checkbox'; name = el.textContent.trim();
      disabled = el.querySelector('input').disabled;
    } else if (el.matches('.widget-colorpicker')) {
      kind = 'colour'; name = label(el);
      disabled = [...el.querySelectorAll('input')].every(i => i.disabled);
    } else if (el.matches('.widget-textarea')) {
      kind = 'textarea'; name = label(el); disabled = el.querySelector('textarea').disabled;
    } else {
      const input = el.querySelector('input');
      if (!input) return;
      kind = input.type === 'number' ? 'number' : 'text'; name = label(el);
      disabled = input.disabled;
    }
    const base = kind + '|' + name;
    seen[base] = (seen[base] || 0) + 1;
    el.setAttribute('data-course-control', String(out.length));
    out.push({key: base + '|' + seen[base], kind, name, disabled, options, selected,
              visible: el.offsetParent !== null && getComputedStyle(el).visibility !== 'hidden'});
  });
  return out;
}"""


#: Controls that choose among options (a mode): every option is visited in turn.
CHOOSERS = ("menu", "toggles")


def controls(view):
    """The view's controls in page order: dicts with key, kind, name, disabled, visible,
    options and selected (for menus and toggle groups) and index (its position, valid until
    the next call)."""
    return [dict(c, index=i) for i, c in enumerate(view.evaluate(_ENUMERATE))]


def destructive(control):
    """A control that takes something away (a "remove" button): operated after the others, so
    that they act on the explorer's full default scene."""
    return control["kind"] == "button" and control["name"].lower().startswith("remove")


def element(view, index):
    return view.locator(f"[data-course-control='{index}']")


#: The figures of a view: ipympl canvases and image widgets (rendered 3D views).
PICTURES = ".jupyter-matplotlib-canvas-div canvas:first-child, img.widget-image"

# The pixels of every picture of a view, read in the page and kept there: a figure's canvas as
# drawn (its backing store) and an image widget at its own size, each over white, with the view's
# text. Python holds a handle; two snapshots are compared in the page. A snapshot costs a few
# milliseconds where an element screenshot (scroll, wait for stable, capture the compositor's
# frame, encode a PNG, decode it in Python) cost 280 ms here, and the controls test takes a few
# hundred snapshots per lesson.
_SNAPSHOT = r"""(root, drop) => {
  const store = window.__courseSnapshots ||
    (window.__courseSnapshots = {next: 0, kept: new Map()});
  for (const id of drop) store.kept.delete(id);
  const pictures = [];
  for (const el of root.querySelectorAll('%s')) {
    const img = el.tagName === 'IMG';
    const w = img ? el.naturalWidth : el.width, h = img ? el.naturalHeight : el.height;
    if (!w || !h || (img && !el.complete)) { pictures.push({w: 0, h: 0, data: null}); continue; }
    const c = new OffscreenCanvas(w, h);
    const ctx = c.getContext('2d', {willReadFrequently: true});
    ctx.fillStyle = '#fff';
    ctx.fillRect(0, 0, w, h);
    ctx.drawImage(el, 0, 0, w, h);
    pictures.push({w, h, data: ctx.getImageData(0, 0, w, h).data});
  }
  const id = store.next++;
  store.kept.set(id, pictures);
  return [id, root.innerText];
}""" % PICTURES

# Pixels of which a colour channel moved by more than `level`, summed over the pictures the two
# snapshots have in common (each pair cropped to the smaller).
_CHANGE = r"""([a, b, level]) => {
  const kept = window.__courseSnapshots.kept;
  const one = kept.get(a), two = kept.get(b);
  let changed = 0;
  for (let k = 0; k < Math.min(one.length, two.length); k++) {
    const p = one[k], q = two[k];
    const w = Math.min(p.w, q.w), h = Math.min(p.h, q.h);
    for (let y = 0; y < h; y++) {
      let i = 4 * y * p.w, j = 4 * y * q.w;
      for (let x = 0; x < w; x++, i += 4, j += 4) {
        const d = Math.max(Math.abs(p.data[i] - q.data[j]),
                           Math.abs(p.data[i + 1] - q.data[j + 1]),
                           Math.abs(p.data[i + 2] - q.data[j + 2]));
        if (d > level) changed++;
      }
    }
  }
  return changed;
}"""

_dropped = []          # (page, id) of snapshots Python no longer holds: freed by the next one


class Pictures:
    """A snapshot's pictures, kept in the page; freed there once Python drops this handle."""

    def __init__(self, page, ident):
        self.page, self.id = page, ident

    def __del__(self):
        _dropped.append((self.page, self.id))


def snapshot(view):
    """The pixels of every picture of the view (a :class:`Pictures` handle) and the view's text
    (its panels and read-outs)."""
    page = view.page
    drop = [ident for p, ident in _dropped if p is page]
    _dropped[:] = [(p, ident) for p, ident in _dropped if p is not page and not p.is_closed()]
    ident, text = view.evaluate(_SNAPSHOT, drop)
    return Pictures(page, ident), text


#: A pixel has changed when a colour channel moved by more than this (the pixels are read
#: losslessly, so this only ignores nothing-but-rounding; a 5 % change of a shading coefficient
#: moves a lit pixel by about 12 levels).
CHANGE_LEVEL = 6


def picture_change(before, after):
    """Pixels that changed between two snapshots' pictures (summed over the figures)."""
    return before[0].page.evaluate(_CHANGE, [before[0].id, after[0].id, CHANGE_LEVEL])


def wait_for_change(view, before, min_pixels, timeout=6.0):
    """Snapshots until the picture changes (then until it is steady) or the time is up.

    Returns the last snapshot and the number of changed pixels against `before`."""
    deadline = time.monotonic() + timeout
    current = snapshot(view)
    while picture_change(before, current) < min_pixels and time.monotonic() < deadline:
        time.sleep(0.12)
        current = snapshot(view)
    if picture_change(before, current) >= min_pixels:
        # steady: the same picture twice in a row (a preview followed by the full image, a
        # drop followed by a full ray cast)
        for _ in range(40):
            time.sleep(0.15)
            again = snapshot(view)
            if picture_change(current, again) == 0:
                break
            current = again
    return current, picture_change(before, current)


_EXAMPLE = re.compile(r"e\.g\.\s*(\S+)")


def choose(view, control, option):
    """Pick option number `option` of a menu or a toggle group."""
    el = element(view, control["index"])
    el.scroll_into_view_if_needed()
    if control["kind"] == "menu":
        el.locator("select").select_option(index=option)
    else:
        el.locator("button").nth(option).click()
    return f"{control['kind']} -> {control['options'][option]!r}"


def operate(view, control):
    """Operate one control (not a chooser) as a student would.

    Returns a description of what was done, and a function that undoes it (None where undoing
    is not one gesture: buttons, typed text)."""
    el = element(view, control["index"])
    page = view.page
    kind = control["kind"]
    el.scroll_into_view_if_needed()
    if kind == "slider":
        handle = el.locator(".noUi-handle").first
        readout = el.locator(".widget-readout").first
        start = readout.inner_text()
        low, now, high = (float(handle.get_attribute(f"aria-value{end}"))
                          for end in ("min", "now", "max"))
        # five steps towards the farther end, as a student nudges a slider with the keyboard
        key, back = ("ArrowRight", "ArrowLeft") if high - now >= now - low else \
            ("ArrowLeft", "ArrowRight")
        handle.focus()
        for _ in range(5):
            page.keyboard.press(key)
            time.sleep(0.02)

        def undo():
            handle.focus()
            for _ in range(12):                        # back to where it started
                if readout.inner_text() == start:
                    break
                page.keyboard.press(back)
                time.sleep(0.02)
            return f"slider back to {readout.inner_text()}"
        return f"slider {start} -> {readout.inner_text()}", undo
    if kind in ("button", "toggle"):
        el.click()
        return "click", ((lambda: el.click() or "clicked again") if kind == "toggle" else None)
    if kind == "checkbox":
        box = el.locator("input")
        box.click()
        return "tick", lambda: box.click() or "unticked"
    if kind == "number":
        field = el.locator("input")
        value = field.input_value()
        high = field.get_attribute("max")
        new = int(float(value or 0)) + 1
        if high is not None and new > float(high):
            new = int(float(value)) - 1
        field.fill(str(new))
        field.press("Enter")
        return f"number {value} -> {new}", None
    if kind == "text":
        field = el.locator("input")
        example = _EXAMPLE.search(field.get_attribute("placeholder") or "")
        text = example.group(1).rstrip(")") if example else "1"
        field.fill(text)
        field.press("Enter")
        return f"typed {text!r}", None
    if kind == "textarea":
        el.locator("textarea").fill("1")
        return "typed '1'", None
    if kind == "colour":                       # the swatch (the browser's colour chooser)
        el.locator("input[type='color']").fill("#2ca02c")
        return "colour -> #2ca02c", None
    raise AssertionError(f"no way to operate a {kind}")


def perform(view, gesture, steps=10):
    """Perform a mouse gesture (a drag, a view turn or a click) on the view's figure canvas; the
    caller waits for the new picture."""
    canvas = view.locator(".jupyter-matplotlib-canvas-div canvas").last   # the top canvas
    canvas.scroll_into_view_if_needed()
    drag_on_canvas(canvas, gesture["start"], gesture["end"],
                   steps=0 if gesture["kind"] == "click" else steps, settle=0)
    return f"{gesture['kind']} {gesture['what']}"


def wait_until_steady(view, timeout=10.0):
    """Snapshots until two in a row, half a second apart, are the same (a view that has just
    been scrolled into sight may still receive its first frames); returns the last one."""
    deadline = time.monotonic() + timeout
    current = snapshot(view)
    while time.monotonic() < deadline:
        time.sleep(0.5)
        again = snapshot(view)
        if picture_change(current, again) == 0 and again[1] == current[1]:
            return again
        current = again
    return current


# Whether any widget model of the open notebook still has a message in flight or held back.
# ipywidgets lets each model have one update in flight until the kernel reports idle for it and
# holds later changes meanwhile; a button of another model is sent at once, so a click made right
# after a slider was moved back could reach the kernel before the slider's last value (then the
# step slider ends where the held value puts it, and its "previous step" button stays greyed
# out). A student's hand is slower than this; the drive waits instead.
_IN_FLIGHT = r"""async () => {
  const panel = window.jupyterapp.shell.currentWidget;
  const managers = new Set();
  for (const cell of panel.content.widgets) {
    const stack = cell.outputArea ? [...cell.outputArea.widgets] : [];
    while (stack.length) {
      const w = stack.pop();
      if (w._manager && w._manager.promise) managers.add(await w._manager.promise);
      if (w.widgets) stack.push(...w.widgets);
    }
  }
  let busy = 0;
  for (const manager of managers)
    for (const model of await Promise.all(Object.values(manager._models)))
      if (model._pending_msgs > 0 || model._msg_buffer !== null) busy++;
  return busy;
}"""


def wait_until_sent(page, timeout=5.0):
    """Wait until every widget update the page made has left it (:data:`_IN_FLIGHT`): what is
    operated next then reaches the kernel after it. Returns the number of models still busy
    when the time was up (0: all sent)."""
    deadline = time.monotonic() + timeout
    while True:
        busy = page.evaluate(_IN_FLIGHT)
        if busy == 0 or time.monotonic() > deadline:
            return busy
        time.sleep(0.05)


def wait_for_return(view, before, tolerance, timeout=20.0):
    """Snapshots until the picture is back to `before` (within `tolerance` pixels); returns
    the number of pixels still different. The wait is long because on a loaded machine the
    kernel may still be drawing the frames of the steps in between (seen: an isoline slider
    back at its value, and its picture 6 s later not yet)."""
    deadline = time.monotonic() + timeout
    while True:
        left = picture_change(before, snapshot(view))
        if left < tolerance or time.monotonic() > deadline:
            return left
        time.sleep(0.12)


def drive(view, gestures, min_pixels, expected=None):
    """Operate every control of one explorer's view, then perform its mouse gestures.

    Every control that is visible and enabled is operated once (a "remove" button after the
    others); every option of every menu and toggle group is chosen in turn, and after each
    choice the controls it enabled are operated too. Each action must change the picture;
    `expected` maps ``(key, option)`` (option None for all of a control) to "text" (the text
    must change instead) or "none" (nothing need change). A slider moved and moved back, or a
    box ticked and unticked, must give the first picture back.

    Returns (what was done, problems), lists of strings."""
    done, problems = [], []
    expected = expected or {}

    def allowed(key, option=None):
        return expected.get((key, option), expected.get((key, None)))

    def check(what, before, changed, after, how=None):
        text_changed = after[1] != before[1]
        line = f"{what}: {changed} px, text {'changed' if text_changed else 'same'}"
        done.append(line)
        if changed < min_pixels and how != "none" and not (how == "text" and text_changed):
            problems.append(line)

    operated, chosen, waited = set(), set(), {}
    park_mouse(view.page)
    wait_until_steady(view)
    while True:
        wait_until_sent(view.page)
        current = [c for c in controls(view) if c["visible"] and not c["disabled"]]
        todo = [c for c in current if c["kind"] not in CHOOSERS and c["key"] not in operated]
        if todo:
            control = min(todo, key=destructive)
            if element(view, control["index"]).is_disabled():
                # greyed out since the list was read (a step button at the first step once the
                # kernel's last answer came): read the list again, as a student looks again
                waited[control["key"]] = waited.get(control["key"], 0) + 1
                if waited[control["key"]] < 25:
                    time.sleep(0.2)
                    continue
                operated.add(control["key"])
                problems.append(f"{control['key']}: listed as enabled 25 times over 5 s, and "
                                "greyed out each time it was to be operated")
                continue
            operated.add(control["key"])
            before = snapshot(view)
            action, undo = operate(view, control)
            how = allowed(control["key"])
            after, changed = wait_for_change(view, before, min_pixels,
                                             timeout=2.0 if how else 6.0)
            check(f"{control['key']}: {action}", before, changed, after, how)
            if undo is not None and changed >= min_pixels:
                how = undo()
                left = wait_for_return(view, before, min_pixels)
                done.append(f"{control['key']}: {how}, {left} px left")
                if left >= min_pixels:
                    problems.append(done[-1] + " (the first picture did not come back)")
            continue
        pending = [(c, k) for c in current if c["kind"] in CHOOSERS
                   for k in range(len(c["options"]))
                   if k != c["selected"] and (c["key"], c["options"][k]) not in chosen]
        if not pending:
            break
        control, option = pending[0]
        chosen.add((control["key"], control["options"][option]))
        operated.add(control["key"])
        before = snapshot(view)
        action = choose(view, control, option)
        how = allowed(control["key"], control["options"][option])
        after, changed = wait_for_change(view, before, min_pixels,
                                         timeout=2.0 if how else 6.0)
        check(f"{control['key']}: {action}", before, changed, after, how)
    never = sorted({c["key"] for c in controls(view) if c["visible"]} - operated)
    if never:
        problems.append(f"never enabled: {never}")
    for gesture in gestures:
        before = snapshot(view)
        action = perform(view, gesture)
        park_mouse(view.page)
        after, changed = wait_for_change(view, before, min_pixels)
        check(action, before, changed, after)
    return done, problems


def park_mouse(page):
    """Move the mouse off every figure: ipympl fades its toolbar in while the mouse is over a
    figure, and the toolbar would count as a changed picture."""
    page.mouse.move(1, 1)
