import { keepTextParenthesesTogether } from '../../../ui/texBreaks';

/** The render lab's explanations, folded: what is drawn, how, and where each piece is taught. */
export function About() {
  return (
    <details className="render-fold">
      <summary>About this lab</summary>
      <p>
        Two renderers compute the same estimator. <code>renderer=gpu</code> (the default) is a WebGL2 fragment
        shader in float32, run from a worker: one path per pixel per frame, summed in a float target both
        naively and by Kahan’s compensated sum, with the sum of squares for each pixel’s noise.{' '}
        <code>renderer=cpu</code> is the core’s float64 path tracer in workers, the ground truth; the pixel
        inspector and the folds below always use it. Without WebGL2 the page draws on the CPU and says why.
        The fold “The two renderers side by side” tests that the GPU’s image agrees with the CPU’s within its
        noise. The run’s timeline is samples per pixel: pausing writes <code>play=0&amp;t=N</code> into the
        link, which renders up to N samples per pixel and holds there.
      </p>
      <p>
        Each pass adds one sample per pixel: a ray through a random point of the pixel, the Q5 quadratic
        against the sphere, and at the hit the direct light estimated by the chosen strategy (uniform or
        cosine hemisphere sampling as in Q1–Q2, the material’s own lobe, Q6’s area sampling, solid-angle
        sampling, or Veach’s balance and power heuristics combining the lobe with the light at equal total
        samples). With more than one bounce the path continues, with Russian roulette after three.
      </p>
      <p>
        relMSE is {keepTextParenthesesTogether('(1/N) Σ (I − R)² / (R² + 0.01)')} over the pixels that have a
        closed-form reference: the exact radiance (Lambert’s polygon formula on an unoccluded Lambertian point
        with one bounce, the furnace’s exact 1, a light’s own radiance) averaged over 3 × 3 points of the
        pixel. Shadowed, glossy and silhouette pixels have none.
      </p>
      <p>
        Sources: E. Veach, <cite>Robust Monte Carlo Methods for Light Transport Simulation</cite> (1997), ch.
        9; M. Pharr, W. Jakob, G. Humphreys, <cite>Physically Based Rendering</cite>, 4th ed., ch. 13; J.
        Arvo, “Stratified sampling of spherical triangles” (1995) and C. Ureña et al., “An area-preserving
        parametrization for spherical rectangles” (2013); J. H. Lambert, <cite>Photometria</cite> (1760); W.
        Kahan, “Further remarks on reducing truncation errors” (1965); N. J. Higham,{' '}
        <cite>Accuracy and Stability of Numerical Algorithms</cite>, 2nd ed. (2002), ch. 4; M. Jarzynski and
        M. Olano, “Hash functions for GPU rendering” (2020).
      </p>
    </details>
  );
}
