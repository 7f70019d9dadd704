/**
 * "Add this view to a deck", in a scene page's share bar: appends the page's link as it stands
 * (its scene state, `ask=1` while the results are held back) to the lecturer's working deck, and
 * says which slide it became, with a link to the deck. A storage that refuses is said, never thrown.
 * The deck's model loads on the first press, not with every scene page.
 */
import { useState } from 'react';

export function AddToDeck({ link }: { link: string }) {
  const [said, setSaid] = useState<{ ok: true; n: number } | { ok: false; message: string } | null>(null);
  return (
    <>
      <button
        type="button"
        data-testid="add-to-deck"
        onClick={() =>
          import('./workingDeck').then(
            (m) => setSaid(m.addToWorkingDeck(link)),
            () => setSaid({ ok: false, message: 'the deck could not be loaded (check the connection)' }),
          )
        }
      >
        Add this view to a deck
      </button>
      <span role="status" className="add-to-deck-status" data-testid="add-to-deck-status">
        {said === null ? null : said.ok ? (
          <>
            Added: slide {said.n} — <a href="#/deck">open the deck</a>
          </>
        ) : (
          `Not added: ${said.message}.`
        )}
      </span>
    </>
  );
}
