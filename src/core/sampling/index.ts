export * from './sphericalCoords';
export * from './uniformHemisphere';
export * from './cosineHemisphere';
