"""What a student sees before any control is touched: every label of an explorer's controls whole,
and the explorer inside its cell's output area.

One ``page.evaluate`` per widget view (:func:`look_problems`) reads, in the browser:

* every control label (``.widget-label``: a slider's, a menu's, a text field's description),
  every check box's text, every button and toggle button and every slider read-out: its text
  is cut (ipywidgets ends it with "..." through ``text-overflow: ellipsis``) when its
  ``scrollWidth`` exceeds its ``clientWidth``;
* every menu (``<select>``): the selected entry's text, measured in the menu's own font,
  must fit the menu's box less its padding (the arrow sits in the right padding);
* every element of the view (but MathJax's invisible copy of a formula for screen readers): its
  right edge must not pass the right edge of the cell's output area (what passes it is clipped
  or scrolled out of sight).
"""

#: Pixels of slack: a width rounded up by the layout engine is not a cut label.
TOLERANCE = 1

_LOOK = r"""(root, tolerance) => {
  const problems = [];
  const shown = (el) => el.offsetParent !== null && getComputedStyle(el).visibility !== 'hidden'
                        && el.getBoundingClientRect().width > 0;
  const text = (el) => el.textContent.trim().replace(/\s+/g, ' ');
  const cut = (el) => el.scrollWidth > el.clientWidth + tolerance;
  const selector = ['.widget-label', '.widget-checkbox label', '.widget-checkbox span',
                    'button.widget-button', 'button.widget-toggle-button',
                    '.widget-readout'].join(', ');
  root.querySelectorAll(selector).forEach(el => {
    if (el.closest('.jupyter-matplotlib-toolbar') || !shown(el) || !text(el)) return;
    if (cut(el)) {
      problems.push(`label cut: '${text(el)}' needs ${el.scrollWidth} px, has ${el.clientWidth}`);
    }
  });
  const canvas = document.createElement('canvas').getContext('2d');
  root.querySelectorAll('.widget-dropdown select').forEach(select => {
    if (!shown(select) || select.selectedIndex < 0) return;
    const style = getComputedStyle(select);
    canvas.font = style.font;
    const option = select.options[select.selectedIndex].textContent.trim();
    const room = select.clientWidth - parseFloat(style.paddingLeft) - parseFloat(style.paddingRight);
    const needs = Math.ceil(canvas.measureText(option).width);
    if (needs > room + tolerance) {
      problems.push(`menu entry cut: '${option}' needs ${needs} px, has ${Math.floor(room)}`);
    }
  });
  const area = root.closest('.jp-OutputArea-output');
  const right = area.getBoundingClientRect().right;
  let widest = null;
  [root, ...root.querySelectorAll('*')].forEach(el => {
    // MathJax's copy of a formula for screen readers is clipped to nothing (not seen)
    if (el.closest('mjx-assistive-mml')) return;
    const box = el.getBoundingClientRect();
    if (box.width === 0 || box.height === 0) return;
    if (box.right > right + tolerance && (widest === null || box.right > widest.right)) {
      widest = {right: box.right, what: el.tagName.toLowerCase() + '.' +
                [...el.classList].slice(0, 2).join('.')};
    }
  });
  if (widest !== null) {
    problems.push(`passes the output area's right edge by ${Math.ceil(widest.right - right)} px` +
                  ` (${widest.what})`);
  }
  return problems;
}"""


def look_problems(view, name):
    """What is cut or clipped in one explorer's widget view, each named after the explorer
    class `name` (an empty list when it looks right)."""
    return [f"{name}: {problem}" for problem in view.evaluate(_LOOK, TOLERANCE)]
