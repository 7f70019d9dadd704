import { practiceSlot } from './extensions';

/** What another feature shows in this place of the page (extensions.ts), if any. */
export function Slot({ name }: { name: 'home-footer' | 'question-footer' }) {
  const C = practiceSlot(name);
  return C ? <C /> : null;
}
