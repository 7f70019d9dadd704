export * from './chi2';
export * from './quadrature';
export * from './hemisphereChi2';
export * from './integrate1d';
