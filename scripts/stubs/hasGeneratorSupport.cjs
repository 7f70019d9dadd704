/**
 * Stands in for @stdlib/assert-has-generator-support in the build (vite.config.ts): that module
 * probes for `function*` by evaluating a string, which the app's Content-Security-Policy refuses
 * (a console error on every page that loads the χ² code, and a wrong answer: the probe then says
 * "no"). Every browser the build targets (ES2022) has generators, so the answer is always yes.
 */
'use strict';

module.exports = function hasGeneratorSupport() {
  return true;
};
