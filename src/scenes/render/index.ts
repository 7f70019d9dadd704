export { schema } from './params';
export { default } from './RenderLab';
export { checkValues } from './check';
