export { schema } from './params';
export { default } from './TextureScene';
export { checkValues } from './check';
