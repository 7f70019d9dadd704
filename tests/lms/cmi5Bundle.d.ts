/** The browser bundle of @xapi/cmi5 (the package's own entry, which Node cannot resolve), typed as the package. */
declare module '@xapi/cmi5/dist/Cmi5.esm.js' {
  export { default } from '@xapi/cmi5';
}
