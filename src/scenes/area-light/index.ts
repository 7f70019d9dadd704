export { schema } from './params';
export { default } from './AreaLightScene';
