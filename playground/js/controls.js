// Form controls for the views: labelled, keyboard-usable native inputs that
// call back on every change and show their value.
'use strict';

(function () {
  let next = 0;

  function labelled(container, text, input, output) {
    const id = `control-${++next}`;
    input.id = id;
    const wrapper = document.createElement('div');
    wrapper.className = 'control';
    const label = document.createElement('label');
    label.htmlFor = id;
    label.textContent = text;
    wrapper.append(label, input);
    if (output) wrapper.append(output);
    container.appendChild(wrapper);
    return wrapper;
  }

  const Controls = {
    /// A range slider; onchange(value) on every move. Returns the input.
    slider(container, text, { min, max, step, value, format }, onchange) {
      const input = document.createElement('input');
      input.type = 'range';
      Object.assign(input, { min, max, step, value });
      const output = document.createElement('output');
      const show = () => { output.textContent = format ? format(Number(input.value)) : input.value; };
      show();
      input.addEventListener('input', () => { show(); onchange(Number(input.value)); });
      labelled(container, text, input, output);
      input.set = (v) => { input.value = v; show(); };
      return input;
    },

    /// A drop-down of [value, text] pairs; onchange(value).
    select(container, text, options, value, onchange) {
      const input = document.createElement('select');
      for (const [v, t] of options) {
        const option = document.createElement('option');
        option.value = v;
        option.textContent = t;
        input.appendChild(option);
      }
      input.value = value;
      input.addEventListener('change', () => onchange(input.value));
      labelled(container, text, input);
      return input;
    },

    /// A checkbox; onchange(checked).
    checkbox(container, text, checked, onchange) {
      const input = document.createElement('input');
      input.type = 'checkbox';
      input.checked = checked;
      input.addEventListener('change', () => onchange(input.checked));
      labelled(container, text, input).classList.add('checkbox');
      return input;
    },

    /// A push button; onclick().
    button(container, text, onclick) {
      const button = document.createElement('button');
      button.type = 'button';
      button.textContent = text;
      button.addEventListener('click', onclick);
      container.appendChild(button);
      return button;
    },
  };

  window.Controls = Controls;
})();
