import { describe, expect, it } from 'vitest';
import { inlineStylesheets, rebaseUrls } from '../../scripts/inlineEntryCss';

const asset = (fileName: string, source: string | Uint8Array) => ({ type: 'asset', fileName, source });

describe('inlineStylesheets: the shell stylesheet inline in index.html', () => {
  const bundle = {
    'assets/index-a1.css': asset('assets/index-a1.css', ':root{--bg:#fff}body{margin:0}'),
    'assets/bytes-b2.css': asset('assets/bytes-b2.css', new TextEncoder().encode('p{color:red}')),
    'assets/font-c3.css': asset('assets/font-c3.css', '@font-face{src:url(./f.woff2)}'),
    'assets/up-d4.css': asset('assets/up-d4.css', '@font-face{src:url(../f.woff2)}'),
    'assets/import-e5.css': asset('assets/import-e5.css', '@import "x.css";p{color:red}'),
    'assets/index-a1.js': { type: 'chunk', fileName: 'assets/index-a1.js' },
  };
  const link = (f: string) => `<link rel="stylesheet" crossorigin href="./${f}">`;

  it('puts the text in a <style> and keeps the link, disabled, for the lazy-chunk loader to find', () => {
    const out = inlineStylesheets(`<head>${link('assets/index-a1.css')}</head>`, bundle, './');
    expect(out).toBe(
      '<head><style>:root{--bg:#fff}body{margin:0}</style>' +
        '<link rel="stylesheet" crossorigin href="./assets/index-a1.css" disabled></head>',
    );
  });

  it('reads a source given as bytes', () => {
    expect(inlineStylesheets(link('assets/bytes-b2.css'), bundle, './')).toContain(
      '<style>p{color:red}</style>',
    );
  });

  it('addresses a relative url() from the page: the stylesheet’s folder in front of it', () => {
    expect(inlineStylesheets(link('assets/font-c3.css'), bundle, './')).toBe(
      '<style>@font-face{src:url(./assets/f.woff2)}</style>' +
        '<link rel="stylesheet" crossorigin href="./assets/font-c3.css" disabled>',
    );
    expect(rebaseUrls(`a{b:url( "x y.png" )}c{d:url('k/l.svg')}`, './assets/')).toBe(
      `a{b:url("./assets/x y.png")}c{d:url('./assets/k/l.svg')}`,
    );
    // absolute addresses, data: URLs and fragments mean the same from anywhere
    const kept = 'a{b:url(/x.png);c:url(data:image/png;base64,AA==);d:url(#m);e:url(https://h/x.png)}';
    expect(rebaseUrls(kept, './assets/')).toBe(kept);
    expect(rebaseUrls('a{b:url(../x.png)}', './assets/')).toBeNull();
  });

  it('leaves alone what it cannot inline safely: a url() that climbs out, @import, files not in the bundle or not assets, other bases', () => {
    for (const tag of [
      link('assets/up-d4.css'),
      link('assets/import-e5.css'),
      link('assets/missing.css'),
      link('assets/index-a1.js'),
      '<link rel="stylesheet" href="https://cdn.example/x.css">',
      '<link rel="stylesheet" href="./assets/index-a1.css" disabled>',
    ])
      expect(inlineStylesheets(tag, bundle, './')).toBe(tag);
    expect(inlineStylesheets(link('assets/index-a1.css'), bundle, '/app/')).toBe(link('assets/index-a1.css'));
  });

  it('does not let a stylesheet close the <style> early', () => {
    const b = { 'assets/x.css': asset('assets/x.css', 'p::after{content:"</style><script>"}') };
    expect(inlineStylesheets(link('assets/x.css'), b, './')).toBe(link('assets/x.css'));
  });
});
