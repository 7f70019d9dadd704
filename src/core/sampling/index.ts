export * from './sphericalCoords';
export * from './uniformHemisphere';
export * from './cosineHemisphere';
export * from './examLobe';
export * from './phongLobe';
export * from './stability';
export * from './pdf1d';
