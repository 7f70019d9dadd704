/** What exam Q5 asks, in the key's words, with the marks it awards. */
export function Q5Asks() {
  return (
    <p className="rs-asks">
      A ray p(t) = <b>o</b> + t <b>d</b> (origin <b>o</b>, direction <b>d</b>, t ≥ 0) is traced against a
      sphere with centre <b>C</b> and radius r. Substitute the ray into the sphere’s equation |p − <b>C</b>|²
      = r² to get a quadratic in t, and state when the ray hits the sphere and which root is the hit.{' '}
      <span className="rs-small">
        (The key awards 2 marks for stating Δ ≥ 0 and 2 marks for stating t ≥ 0.)
      </span>
    </p>
  );
}
