// What the cooperative gestures' hint says (DOM-free, so the tests read the same words).

/** A plain wheel over the map: the modifier that makes it zoom (⌘ on a Mac). */
export function wheelHint(mac: boolean): string {
  return `Use ${mac ? '⌘' : 'Ctrl'} + scroll to zoom the map`;
}

/** One finger on the map. */
export const TOUCH_HINT = 'Use two fingers to move the map';
