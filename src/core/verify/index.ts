export * from './chi2';
export * from './sidak';
export * from './quadrature';
export * from './hemisphereChi2';
export * from './integrate1d';
export * from './studentT';
export * from './ttest';
export * from './welchMap';
