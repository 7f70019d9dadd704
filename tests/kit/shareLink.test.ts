import { describe, expect, it } from 'vitest';
import { serializeParams, type ParamSchema } from '../../src/kit/params';
import { shareBase, sharedFlags, shareUrl, type ShareMode } from '../../src/kit/shareLink';
import { embedSnippet } from '../../src/app/embedCode';
import { variantHref, variantUrl } from '../../src/practice/Sheet';

const PRIVATE = /userid|email|fullname|token|fetch|actor|registration|endpoint|4242|ada%40|ada@/i;

describe('shared links carry the app’s own route only', () => {
  const pages = [
    'https://lab.example/app/?userid=4242&email=ada%40example.org&fullname=Ada+L#/texture?u=0.7',
    'https://lms.example/pkg/index.html?endpoint=http%3A%2F%2F127.0.0.1%3A9%2Fxapi&fetch=http%3A%2F%2F127.0.0.1%3A9%2Ftoken%3Fk%3Dabc&actor=%7B%22mbox%22%3A%22mailto%3Aada%40example.org%22%7D&registration=r-1&activityId=urn%3Aa&rml-au=q3#/practice/q3?seed=5',
    'file:///home/ada/lab/index.html?token=s3cret#/guide',
    'https://lab.example/?a=1?b=2#/x',
  ];
  it('drops the page’s query string and fragment', () => {
    expect(shareBase(pages[0])).toBe('https://lab.example/app/');
    expect(shareBase(pages[1])).toBe('https://lms.example/pkg/index.html');
    expect(shareBase(pages[2])).toBe('file:///home/ada/lab/index.html');
    expect(shareBase(pages[3])).toBe('https://lab.example/');
    expect(shareBase('https://lab.example/#/x?email=a')).toBe('https://lab.example/');
  });
  it('the worksheet’s links keep the variant and nothing of the page’s query', () => {
    for (const page of pages) {
      const url = variantUrl({ question: 'q3', seed: 17 }, page);
      const href = variantHref({ question: 'q3', seed: 17 }, page);
      expect(url).toBe(`${shareBase(page)}#/practice/q3?seed=17`);
      expect(href).toBe(`${shareBase(page)}?utm_source=worksheet#/practice/q3?seed=17`);
      expect(url).not.toMatch(PRIVATE);
      expect(href).not.toMatch(PRIVATE);
    }
  });
  it('Copy link, the QR code and the embed code carry nothing of other launches either', () => {
    // other LMSs and course pages than the ones above: LTI fields, a session in the path, a login
    // in the address, a launch whose values are encoded twice, an empty fragment
    const others = [
      'https://moodle.example/mod/pkg/index.html?user_id=4242&lis_person_contact_email_primary=ada%40example.org&lis_person_name_full=Ada%20L&oauth_signature=abc#/ray-sphere?ox=0.5',
      'https://lms.example/pkg;jsessionid=S3SS10N/index.html;token=abc?x=1#/hemisphere',
      'https://ada:p4ss@lms.example:8443/pkg/index.html?Email=ADA%40EXAMPLE.ORG#',
      'http://127.0.0.1:5173/?actor=%257B%2522mbox%2522%253A%2522mailto%253Aada%2540example.org%2522%257D&fetch=http%253A%252F%252Fx%252Ftoken#/monte-carlo',
      'file:///C:/Users/ada/lab/index.html?registration=r-9&endpoint=https%3A%2F%2Flrs.example#/area-light',
    ];
    const expected = [
      'https://moodle.example/mod/pkg/index.html',
      'https://lms.example/pkg/index.html',
      'https://lms.example:8443/pkg/index.html',
      'http://127.0.0.1:5173/',
      'file:///C:/Users/ada/lab/index.html',
    ];
    const leaks =
      /user_id|lis_|oauth|jsession|S3SS10N|token|p4ss|ada:|email|actor|fetch|registration|endpoint|4242|ada(%25)?(%40|@)/i;
    others.forEach((page, i) => {
      expect(shareBase(page)).toBe(expected[i]);
      const link = shareUrl(page, '/texture', 'u=0.7&v=0.2');
      expect(link).toBe(`${expected[i]}#/texture?u=0.7&v=0.2`);
      expect(shareUrl(page, '/texture', '')).toBe(`${expected[i]}#/texture`);
      expect(embedSnippet(shareUrl(page, '/texture', 'embed=1'), 'Texture', 'texture')).not.toMatch(leaks);
      expect(link).not.toMatch(leaks);
    });
  });
});

describe('the link Copy link and the QR code hand out', () => {
  const schema = {
    u: { kind: 'number', default: 0.5, min: 0, max: 1 },
  } as const satisfies ParamSchema;
  const lms = 'https://lab.example/app/?userid=4242&email=ada%40example.org#/texture?u=0.7&present=1&ask=1';
  const mode = (m: Partial<ShareMode>): ShareMode => ({
    present: false,
    asking: false,
    keep: false,
    part: null,
    theme: null,
    ...m,
  });
  const link = (m: Partial<ShareMode>) =>
    shareUrl(lms, '/texture', serializeParams(schema, { u: 0.7 }, sharedFlags(mode(m))));

  it('in classroom mode keeps present=1 and, while the results are held back, ask=1', () => {
    const asking = link({ present: true, asking: true, part: '3b' });
    expect(asking).toBe('https://lab.example/app/#/texture?u=0.7&part=3b&present=1&ask=1');
    expect(asking).not.toMatch(PRIVATE);
    // revealed: still classroom mode, no longer asking
    expect(link({ present: true })).toBe('https://lab.example/app/#/texture?u=0.7&present=1');
    // the "keep" choice belongs to the page outside classroom mode: it changes nothing here
    expect(link({ present: true, asking: true, keep: true })).toBe(link({ present: true, asking: true }));
  });
  it('outside classroom mode is the students’ view unless the lecturer keeps ask=1', () => {
    expect(link({ asking: true })).toBe('https://lab.example/app/#/texture?u=0.7');
    expect(link({ asking: true, keep: true })).toBe('https://lab.example/app/#/texture?u=0.7&ask=1');
    // nothing held back: nothing to keep
    expect(link({ keep: true })).toBe('https://lab.example/app/#/texture?u=0.7');
  });
  it('keeps the part and the theme, and nothing of the page’s own query', () => {
    const l = link({ present: true, asking: true, part: '3a', theme: 'dark' });
    expect(l).toBe('https://lab.example/app/#/texture?u=0.7&part=3a&present=1&ask=1&theme=dark');
    expect(l).not.toMatch(PRIVATE);
    expect(shareUrl(lms, '/texture', '')).toBe('https://lab.example/app/#/texture');
  });
});
