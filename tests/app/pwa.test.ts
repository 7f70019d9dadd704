/**
 * The service-worker registration in a page: a browser that blocks service workers (as automated
 * ones do) resolves the registration with nothing, which must pass quietly; a new build's waiting
 * worker on a controlled page is offered as an update.
 */
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';

const shown = vi.fn();
vi.mock('../../src/app/updateNotice', () => ({ showUpdateNotice: shown }));

function stubPage(register: () => Promise<unknown>, controller: unknown = null) {
  vi.stubGlobal('document', {
    baseURI: 'http://127.0.0.1/app/',
    querySelector: () => null,
    createElement: () => ({}),
    head: { append: () => {} },
    addEventListener: () => {},
    visibilityState: 'visible',
  });
  vi.stubGlobal('navigator', { serviceWorker: { register, controller, addEventListener: () => {} } });
  vi.stubGlobal('window', { setInterval: () => 0 });
}

beforeEach(() => shown.mockClear());
afterEach(() => vi.unstubAllGlobals());

describe('registerPwa', () => {
  it('a registration that resolves with nothing passes quietly (no property read on undefined)', async () => {
    stubPage(async () => undefined);
    const { registerPwa } = await import('../../src/app/pwa');
    await expect(registerPwa()).resolves.toBeUndefined();
    expect(shown).not.toHaveBeenCalled();
  });
  it('a refused registration passes quietly too', async () => {
    stubPage(async () => {
      throw new Error('blocked');
    });
    const { registerPwa } = await import('../../src/app/pwa');
    await expect(registerPwa()).resolves.toBeUndefined();
  });
  it('a waiting worker on a controlled page is offered as an update; on a first install it is not', async () => {
    const reg = { waiting: {}, installing: null, addEventListener: () => {}, update: async () => {} };
    stubPage(async () => reg, {});
    const { registerPwa } = await import('../../src/app/pwa');
    await registerPwa();
    expect(shown).toHaveBeenCalledTimes(1);
    stubPage(async () => reg, null);
    await registerPwa();
    expect(shown).toHaveBeenCalledTimes(1);
  });
});
