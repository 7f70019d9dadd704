// KaTeX's stylesheet split in two by scripts/katexCss.ts: its @font-face rules, and the rest
declare module 'katex/dist/katex.min.css?fonts';
declare module 'katex/dist/katex.min.css?rules';
