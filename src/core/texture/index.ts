export * from './addressing';
export * from './grid';
export * from './lookup';
export * from './spherical';
