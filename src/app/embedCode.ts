/** The "Copy embed code" snippet: an iframe with an id, and the listener that sizes it. */

/** A short stable hash (FNV-1a) so that two embeds of different configurations get different ids. */
function shortHash(s: string): string {
  let h = 0x811c9dc5;
  for (let i = 0; i < s.length; i++) {
    h ^= s.charCodeAt(i);
    h = Math.imul(h, 0x01000193);
  }
  return (h >>> 0).toString(36).slice(0, 6);
}

function attr(s: string): string {
  return s.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');
}

/**
 * The iframe and a script that resizes it from the scene's height messages. The script checks
 * that a message comes from this iframe (so several embeds on one page do not mix) and reads only
 * a number from it.
 */
export function embedSnippet(src: string, title: string, sceneId: string): string {
  const id = `rml-${sceneId.replace(/[^a-z0-9-]/gi, '')}-${shortHash(src)}`;
  return [
    `<iframe id="${id}" src="${attr(src)}" title="${attr(title)}" width="100%" height="720" style="border:0" loading="lazy"></iframe>`,
    `<script>`,
    `addEventListener('message', function (e) {`,
    `  var f = document.getElementById('${id}');`,
    `  if (!f || e.source !== f.contentWindow || !e.data || e.data.type !== 'render-math-lab:height') return;`,
    `  var h = Number(e.data.height);`,
    `  if (h > 0 && h < 100000) f.style.height = Math.ceil(h) + 'px';`,
    `});`,
    `</script>`,
  ].join('\n');
}
