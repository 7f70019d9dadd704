export * from './addressing';
export * from './grid';
export * from './lookupOptions';
export * from './nearest';
export * from './bilinear';
export * from './reconstruct';
export * from './spherical';
