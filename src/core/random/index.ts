export * from './rng';
export * from './owen';
export * from './sobol';
export * from './sequences';
