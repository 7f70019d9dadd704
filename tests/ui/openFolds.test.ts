// The page's list of open folds (src/ui/openFolds.ts) where no fold listens: read from the address.
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';

const fakeWindow = {
  location: { hash: '' },
  addEventListener: () => undefined,
  removeEventListener: () => undefined,
  history: { state: null, replaceState: () => undefined },
};

describe('getOpenFolds', () => {
  beforeEach(() => {
    vi.resetModules();
    vi.stubGlobal('window', fakeWindow);
  });
  afterEach(() => {
    vi.unstubAllGlobals();
  });

  it('follows the address while nothing listens, a link followed between two pages included', async () => {
    const { getOpenFolds } = await import('../../src/ui/openFolds');
    fakeWindow.location.hash = '#/monte-carlo?open=race-data';
    expect(getOpenFolds()).toEqual(['race-data']);
    // the reader leaves for the home page, then follows a link that opens two folds
    fakeWindow.location.hash = '#/';
    expect(getOpenFolds()).toEqual([]);
    fakeWindow.location.hash = '#/hemisphere?n=64&open=settings,more';
    expect(getOpenFolds()).toEqual(['settings', 'more']);
  });

  it('gives the same array while the list is unchanged (a stable snapshot for React)', async () => {
    const { getOpenFolds } = await import('../../src/ui/openFolds');
    fakeWindow.location.hash = '#/texture?open=edit&u=0.4';
    const first = getOpenFolds();
    fakeWindow.location.hash = '#/texture?u=0.5&open=edit';
    expect(getOpenFolds()).toBe(first);
  });
});
