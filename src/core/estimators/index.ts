export * from './welford';
export * from './estimate';
export * from './convergence';
export * from './rmse';
export * from './slope';
export * from './run1d';
export * from './histogram';
