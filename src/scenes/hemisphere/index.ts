/** Scene `#/hemisphere` (exam Q1, Q2). The shell loads this module lazily. */
export { schema } from './params';
export { default } from './HemisphereScene';
export { checkValues } from './check';
