/** The guide's ready decks (src/deck/readyDecks.ts) and the working deck in storage (workingDeck.ts). */
import { describe, expect, it } from 'vitest';
import { readyDeck, READY_QUESTIONS } from '../../src/deck/readyDecks';
import { LESSONS } from '../../src/guide/lessons';
import { readDeck } from '../../src/deck/deck';
import {
  addToWorkingDeck,
  loadWorkingDeck,
  saveWorkingDeck,
  WORKING_DECK_KEY,
} from '../../src/deck/workingDeck';
import { setLearnerScope } from '../../src/practice/learnerScope';
import { freshWindowEachTest } from '../practice/memoryWindow';

describe('ready decks', () => {
  it('each guide question is a deck of its presets, in order, asking first where the preset does', () => {
    for (const n of READY_QUESTIONS) {
      const deck = readyDeck(n)!;
      const lesson = LESSONS.find((l) => l.id === `q${n}`)!;
      expect(deck.title).toMatch(new RegExp(`^Q${n} · `));
      expect(deck.slides.map((s) => s.title)).toEqual(lesson.presets.map((p) => p.title));
      expect(deck.slides.map((s) => s.question)).toEqual(lesson.presets.map((p) => p.ask));
      expect(deck.slides.map((s) => s.link.endsWith('ask=1'))).toEqual(
        lesson.presets.map((p) => !!p.askFirst),
      );
      expect(readDeck(deck)).toEqual({ ok: true, value: deck });
    }
    expect(readyDeck(7)).toBeNull();
  });
});

describe('the working deck', () => {
  const storage = freshWindowEachTest();
  it('starts empty, appends links and says the new slide number', () => {
    expect(loadWorkingDeck()).toEqual({ deck: { title: 'My deck', slides: [] }, problem: null });
    expect(addToWorkingDeck('https://x.org/#/texture?u=0.4&present=1')).toEqual({ ok: true, n: 1 });
    expect(addToWorkingDeck('#/hemisphere?ask=1')).toEqual({ ok: true, n: 2 });
    expect(loadWorkingDeck().deck.slides.map((s) => s.link)).toEqual(['/texture?u=0.4', '/hemisphere?ask=1']);
    expect(addToWorkingDeck('#/guide')).toEqual({ ok: false, message: expect.stringMatching(/not a scene/) });
  });
  it('is kept per learner', () => {
    addToWorkingDeck('#/texture');
    setLearnerScope('student-7');
    expect(loadWorkingDeck().deck.slides).toEqual([]);
    setLearnerScope(null);
    expect(loadWorkingDeck().deck.slides.length).toBe(1);
  });
  it('says, never throws, when storage holds junk or refuses', () => {
    storage.local.setItem(WORKING_DECK_KEY, '{"format":"render-math-lab-deck","version":1,"slides":7}');
    expect(loadWorkingDeck().problem).toMatch(
      /the stored deck could not be read \(the deck has no list of slides\)/,
    );
    storage.local.setItem = () => {
      throw new Error('QuotaExceededError');
    };
    expect(saveWorkingDeck({ title: 'x', slides: [] })).toMatch(/could not be stored/);
    expect(addToWorkingDeck('#/texture')).toEqual({
      ok: false,
      message: expect.stringMatching(/could not be stored/),
    });
    storage.local.getItem = () => {
      throw new Error('SecurityError');
    };
    expect(loadWorkingDeck().problem).toMatch(/does not let the page read its storage/);
    expect(addToWorkingDeck('#/texture')).toEqual({
      ok: false,
      message: expect.stringMatching(/does not let/),
    });
  });
});
