export { schema } from './params';
export { default } from './AreaLightScene';
export { checkValues } from './check';
