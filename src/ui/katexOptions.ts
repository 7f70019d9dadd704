/** KaTeX's options, the same in the worker and in the main-thread fallback (src/ui/MathTex.tsx). */
export const KATEX_OPTIONS = { throwOnError: false, strict: 'ignore', output: 'htmlAndMathml' } as const;
