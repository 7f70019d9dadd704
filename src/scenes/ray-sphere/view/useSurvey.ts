/**
 * The t_min survey (secondary rays from points spread over the sphere), cast on the main thread in
 * short slices after the block that shows it has mounted: the rays are a few ms of cold code, which
 * in one piece would be one long task while the page opens.
 */
import { useEffect, useState } from 'react';
import { runChunked } from '../../../ui';
import type { RaySphereMethod } from '../../../core/geometry';
import { selfIntersectionSurveyRange, type SurveyCounts } from '../secondaryRay';

/** Points of the survey, and how many are cast per queued job. */
export const SURVEY_POINTS = 1000;
const SURVEY_CHUNK = 200;

/** The survey's counts for this sphere and method, or null while the rays are still being cast. */
export function useSurvey(cx: number, cy: number, cz: number, r: number, method: RaySphereMethod) {
  const key = `${cx},${cy},${cz},${r},${method}`;
  const [done, setDone] = useState<{ key: string; survey: SurveyCounts } | null>(null);
  useEffect(() => {
    const acc: SurveyCounts = { count: 0, withZero: 0, withTMin: 0 };
    const cancels: (() => void)[] = [];
    for (let k = 0; k < SURVEY_POINTS; k += SURVEY_CHUNK) {
      const k0 = k;
      cancels.push(
        runChunked(() => {
          const part = selfIntersectionSurveyRange(
            [cx, cy, cz],
            r,
            method,
            SURVEY_POINTS,
            k0,
            k0 + SURVEY_CHUNK,
          );
          acc.count += part.count;
          acc.withZero += part.withZero;
          acc.withTMin += part.withTMin;
          if (k0 + SURVEY_CHUNK >= SURVEY_POINTS)
            setDone({ key: `${cx},${cy},${cz},${r},${method}`, survey: acc });
        }),
      );
    }
    return () => cancels.forEach((cancel) => cancel());
  }, [cx, cy, cz, r, method]);
  return done?.key === key ? done.survey : null;
}
