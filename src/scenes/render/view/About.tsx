/** The render lab's explanations, folded: what is drawn, how, and where each piece is taught. */
export function About() {
  return (
    <details className="render-fold">
      <summary>About this lab</summary>
      <p>
        The renderer is the core’s float64 CPU path tracer, run in workers; <code>renderer</code> accepts only{' '}
        <code>cpu</code> for now (a WebGL2 renderer is not built yet).
      </p>
      <p>
        Each pass adds one sample per pixel: a ray through a random point of the pixel, the Q5 quadratic
        against the sphere, and at the hit the direct light estimated by the chosen strategy (uniform or
        cosine hemisphere sampling as in Q1–Q2, the material’s own lobe, Q6’s area sampling, solid-angle
        sampling, or Veach’s balance and power heuristics combining the lobe with the light at equal total
        samples). With more than one bounce the path continues, with Russian roulette after three.
      </p>
      <p>
        relMSE is (1/N) Σ (I − R)² / (R² + 0.01) over the pixels that have a closed-form reference: the exact
        radiance (Lambert’s polygon formula on an unoccluded Lambertian point with one bounce, the furnace’s
        exact 1, a light’s own radiance) averaged over 3 × 3 points of the pixel. Shadowed, glossy and
        silhouette pixels have none.
      </p>
      <p>
        Sources: E. Veach, <cite>Robust Monte Carlo Methods for Light Transport Simulation</cite> (1997), ch.
        9; M. Pharr, W. Jakob, G. Humphreys, <cite>Physically Based Rendering</cite>, 4th ed., ch. 13; J.
        Arvo, “Stratified sampling of spherical triangles” (1995) and C. Ureña et al., “An area-preserving
        parametrization for spherical rectangles” (2013); J. H. Lambert, <cite>Photometria</cite> (1760).
      </p>
    </details>
  );
}
