/** The strategies (pdf · point set) the convergence plots compare, and their labels. */
import type { PdfKind, Strategy } from './params';

/** The strategies compared in the convergence plots: [pdf, sequence, label]. */
export function comparedStrategies(
  selPdf: PdfKind,
  selSeq: Strategy,
  pdfOk: boolean,
): { pdf: PdfKind; seq: Strategy; label: string }[] {
  // each pdf with independent samples, then the uniform pdf with each better-spread sequence
  const pdfs: PdfKind[] = ['uniform', 'linear', 'proportional'];
  const seqs: Strategy[] = ['stratified', 'sobol'];
  type Compared = { pdf: PdfKind; seq: Strategy };
  const base: Compared[] = [
    ...pdfs.map((pdf): Compared => ({ pdf, seq: 'independent' })),
    ...seqs.map((seq): Compared => ({ pdf: 'uniform', seq })),
  ];
  if (pdfOk && !base.some((s) => s.pdf === selPdf && s.seq === selSeq))
    base.push({ pdf: selPdf, seq: selSeq });
  return base.map((s) => ({ ...s, label: strategyLabel(s.pdf, s.seq) }));
}

const PDF_LABEL: Record<PdfKind, string> = {
  uniform: 'uniform',
  linear: 'linear',
  proportional: 'p ∝ f',
  custom: 'custom p',
};
const SEQ_LABEL: Record<Strategy, string> = {
  independent: 'independent',
  stratified: 'stratified',
  halton: 'Halton',
  sobol: 'Sobol',
};

/** "uniform · Sobol" etc. */
export function strategyLabel(pdf: PdfKind, seq: Strategy): string {
  return `${PDF_LABEL[pdf]} · ${SEQ_LABEL[seq]}`;
}

/** Order (x, y) points by x, so a curve against measured time never doubles back. */
export function sortedByX<T extends { x: number }>(pts: readonly T[]): T[] {
  return [...pts].sort((p, q) => p.x - q.x);
}
