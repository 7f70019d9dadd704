export { Viewport } from './Viewport';
export type { ViewportContext, ViewportProps } from './Viewport';
