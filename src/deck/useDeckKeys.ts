/**
 * The deck's keys: → / PageDown / Space next, ← / PageUp previous, Home / End first / last, `b` a
 * black screen (any key, or a click, brings the slide back). They are heard before the page's other
 * keys (a capture listener on window), so Space turns the slide instead of playing the scene's
 * animation; they are left alone while typing in a field, while a figure of the slide has focus
 * (its arrows move what it shows) and, for Space, on a focused button or link (it presses it).
 * `v` (reveal) is the slide's own.
 */
import { useEffect, useRef } from 'react';
import { isTyping } from '../ui/shortcuts';

export interface DeckKeyActions {
  next: () => void;
  previous: () => void;
  first: () => void;
  last: () => void;
  black: () => void;
  /** The screen is black: any key brings the slide back. */
  blackedOut: boolean;
  unblack: () => void;
}

/** What a key does on the deck, or null for a key the deck leaves to the page. */
export function deckKeyAction(
  key: string,
  where: { figure: boolean; pressable: boolean },
): keyof Omit<DeckKeyActions, 'blackedOut' | 'unblack'> | null {
  if (key === 'b' || key === 'B') return 'black';
  if (key === ' ' || key === 'Spacebar') return where.figure || where.pressable ? null : 'next';
  if (where.figure) return null;
  if (key === 'ArrowRight' || key === 'PageDown') return 'next';
  if (key === 'ArrowLeft' || key === 'PageUp') return 'previous';
  if (key === 'Home') return 'first';
  if (key === 'End') return 'last';
  return null;
}

/** A focused part of the slide that takes keys itself: a figure, slider, canvas or 3D view. */
function inFigure(target: EventTarget | null): boolean {
  if (!(target instanceof Element)) return false;
  const slide = target.closest('.deck-stage');
  if (!slide || target === slide) return false;
  const own = target.closest(
    '[role="slider"], [role="application"], [role="radiogroup"], canvas, [tabindex="0"]',
  );
  return !!own && slide.contains(own);
}

function isPressable(target: EventTarget | null): boolean {
  return (
    target instanceof Element &&
    !!target.closest('button, a[href], summary, [role="button"], [role="checkbox"], [role="radio"], input')
  );
}

const MODIFIERS = new Set(['Shift', 'Control', 'Alt', 'Meta', 'CapsLock']);

export function useDeckKeys(actions: DeckKeyActions, active: boolean): void {
  const ref = useRef(actions);
  ref.current = actions;
  useEffect(() => {
    if (!active) return;
    const on = (e: KeyboardEvent) => {
      const a = ref.current;
      if (a.blackedOut) {
        if (MODIFIERS.has(e.key)) return;
        e.preventDefault();
        e.stopPropagation();
        a.unblack();
        return;
      }
      if (e.defaultPrevented || e.ctrlKey || e.metaKey || e.altKey || isTyping(e.target)) return;
      const action = deckKeyAction(e.key, { figure: inFigure(e.target), pressable: isPressable(e.target) });
      if (!action) return;
      e.preventDefault();
      e.stopPropagation();
      a[action]();
    };
    window.addEventListener('keydown', on, true);
    return () => window.removeEventListener('keydown', on, true);
  }, [active]);
}
