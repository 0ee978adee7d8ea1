// What the container shows where the browser has no WebGL2.

export function showWebGl2Missing(container: HTMLElement): HTMLElement {
  const box = document.createElement('div');
  box.className = 'ssc-message ssc-no-webgl2';
  box.setAttribute('role', 'alert');
  box.style.cssText = 'position:absolute;inset:0;display:flex;align-items:center;justify-content:center;padding:1em;text-align:center;font:14px/1.4 system-ui,sans-serif;color:#333;background:#f4f4f4';
  box.textContent = 'This map needs WebGL2, which this browser does not offer (or has turned off). Try a current version of Firefox, Chrome, Edge or Safari, or turn hardware acceleration on.';
  container.appendChild(box);
  return box;
}
