/**
 * The colours of the rendered sphere images (the distant-sphere renders and the GPU panel): a dark
 * background, the lit sphere, and the pink of a hit the method lost. The images are their own
 * dark pictures in both themes (the page's theme does not change them).
 */
export type Rgb = [number, number, number];

export const IMAGE_BG: Rgb = [32, 35, 42];
export const IMAGE_FG: Rgb = [236, 228, 206];
export const IMAGE_HOLE: Rgb = [255, 45, 149];
