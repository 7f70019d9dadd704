export * from './raySphere';
export * from './raySphereReference';
export * from './doubleDouble';
export * from './ulp';
export * from './solidAngle';
export * from './raySphereF32';
export * from './ulp32';
export * from './raySphereImageF32';
