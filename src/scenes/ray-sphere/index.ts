/** #/ray-sphere (exam Q5): URL schema and the scene component. */
export { schema } from './params';
export { default } from './RaySphereScene';
export { checkValues } from './check';
