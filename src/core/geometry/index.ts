export * from './raySphere';
export * from './raySphereReference';
export * from './doubleDouble';
export * from './ulp';
export * from './solidAngle';
