// The write-up's comparison sliders: the range input under two renders, or a pointer on them,
// moves the split between the left render (clipped on top) and the right one beneath it.
'use strict';
for (const slider of document.querySelectorAll('.slider')) {
  const view = slider.querySelector('.slider-view');
  const range = slider.querySelector('.slider-range');
  const show = (percent) => {
    const p = Math.min(100, Math.max(0, percent));
    view.style.setProperty('--split', `${p}%`);
    slider.dataset.split = String(p);
    if (Number(range.value) !== p) range.value = String(p);
  };
  range.addEventListener('input', () => show(Number(range.value)));
  const follow = (event) => {
    const box = view.getBoundingClientRect();
    show(((event.clientX - box.left) / box.width) * 100);
  };
  // A press on a picture would otherwise start dragging the image itself, which ends the
  // pointer's capture after its first move.
  view.addEventListener('dragstart', (event) => event.preventDefault());
  view.addEventListener('pointerdown', (event) => {
    event.preventDefault();
    view.setPointerCapture(event.pointerId);
    follow(event);
  });
  view.addEventListener('pointermove', (event) => {
    if (view.hasPointerCapture(event.pointerId)) follow(event);
  });
  show(Number(range.value));
}
