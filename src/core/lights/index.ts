export * from './rectLight';
export * from './areaSampling';
export * from './sphericalRectangle';
export * from './polygonIrradiance';
export * from './areaLightEstimators';
