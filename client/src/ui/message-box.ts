// A message over the whole map (no WebGL2, a cube that cannot be loaded), announced to screen
// readers at once. Styled inline: it must be readable even when the stylesheet is missing.

export function showMessageBox(container: HTMLElement, className: string, lines: string[]): HTMLElement {
  const box = document.createElement('div');
  box.className = `ssc-message ${className}`;
  box.setAttribute('role', 'alert');
  box.style.cssText = 'position:absolute;inset:0;display:flex;flex-direction:column;align-items:center;justify-content:center;gap:0.5em;padding:1em;text-align:center;overflow-wrap:anywhere;font:14px/1.4 system-ui,sans-serif;color:#333;background:#f4f4f4';
  for (const line of lines) {
    const p = document.createElement('p');
    p.style.margin = '0';
    p.textContent = line;
    box.appendChild(p);
  }
  container.appendChild(box);
  return box;
}
