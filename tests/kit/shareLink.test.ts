import { describe, expect, it } from 'vitest';
import { shareBase } from '../../src/kit/shareLink';
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
});
