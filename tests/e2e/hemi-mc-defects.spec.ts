/**
 * Browser tests of user-facing defects in the hemisphere scene's Q1: each figure printed is right
 * to every digit shown, text reads as written, and a figure with nothing to sample says so.
 */
import { test, expect, openScene } from './fixtures';
import { examLobeK } from '../../src/core/sampling';
import { formatNumber } from '../../src/ui/Readout';

test('a typed density: its k is right to every digit printed, and the exam’s k stays the exam’s', async ({
  page,
}) => {
  // p ∝ cos³θ e^{φ/2}: ∫ p dω = ¼ · 2(e^π − 1), so k = 2/(e^π − 1)
  await openScene(page, '#/hemisphere?lobe=custom&pdf=cos(theta)^3*exp(phi/2)');
  const chosen = page.getByTestId('k-chosen');
  await expect(chosen).toHaveText(formatNumber(2 / Math.expm1(Math.PI), 8));
  await expect(page.getByTestId('other-lobe')).toContainText('adaptive quadrature');
  await expect(page.getByTestId('answer-1a').getByTestId('k')).toHaveAttribute(
    'data-value',
    String(examLobeK()),
  );
});

test('Q1(b): the key’s stray e^φ is followed by a space', async ({ page }) => {
  await openScene(page, '#/hemisphere');
  await expect(page.getByTestId('keynote-stray-ephi')).toContainText('eφ outside the integral');
});

test('the paper’s Jacobian: the caption says nothing is drawn and Play is disabled', async ({ page }) => {
  await openScene(page, '#/hemisphere?jacobian=inverted');
  await expect(page.getByTestId('hemi-caption').first()).toContainText('Nothing is drawn');
  await expect(
    page.getByTestId('timeline-nothing').getByRole('button', { name: /play/i }).first(),
  ).toBeDisabled();
});
