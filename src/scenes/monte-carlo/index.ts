export { schema } from './params';
export { default } from './MonteCarloScene';
export { checkValues } from './check';
