#!/usr/bin/env node
/**
 * LDR-FLIP between two PNG images, as NVIDIA's FLIP tool reports it:
 *
 *     node scripts/flip.mjs REFERENCE.png TEST.png [--ppd N] [--map OUT.png]
 *
 * prints the mean, the weighted median and quartiles, the minimum and the maximum of the per-pixel
 * error, and with --map writes the error map coloured by magma (0 black … 1 pale yellow). --ppd is
 * the observer's pixels per degree (default: 0.7 m from a 0.7 m wide display 3840 pixels across,
 * about 67). The computation is the app's own, src/core/image/flip.ts.
 */
import { readFileSync, writeFileSync } from 'node:fs';
import { loadTs } from './loadTs.mjs';

const usage = 'usage: node scripts/flip.mjs REFERENCE.png TEST.png [--ppd N] [--map OUT.png]';
const args = process.argv.slice(2);
const files = [];
let ppd;
let mapOut;
for (let i = 0; i < args.length; i++) {
  if (args[i] === '--ppd') ppd = Number(args[++i]);
  else if (args[i] === '--map') mapOut = args[++i];
  else if (args[i] === '-h' || args[i] === '--help') {
    console.log(usage);
    process.exit(0);
  } else files.push(args[i]);
}
if (files.length !== 2 || (ppd !== undefined && !(ppd > 0)) || (args.includes('--map') && !mapOut)) {
  console.error(usage);
  if (ppd !== undefined && !(ppd > 0)) console.error(`--ppd must be a positive number`);
  process.exit(2);
}

const { decodePng, encodePng, rgbFromRgba8 } = await loadTs('src/core/image/png.ts');
const { flipErrorMap, DEFAULT_PPD } = await loadTs('src/core/image/flip.ts');
const { poolError } = await loadTs('src/core/image/pooling.ts');
const { magmaErrorImage } = await loadTs('src/core/image/flipRgba8.ts');

function read(path) {
  try {
    return rgbFromRgba8(decodePng(new Uint8Array(readFileSync(path))));
  } catch (e) {
    console.error(`${path}: ${e.message}`);
    process.exit(1);
  }
}
const ref = read(files[0]);
const test = read(files[1]);
let map;
try {
  map = flipErrorMap(ref, test, ppd ?? DEFAULT_PPD);
} catch (e) {
  console.error(e.message);
  process.exit(1);
}
const p = poolError(map);
const f = (x) => x.toFixed(6);
console.log(`pixels per degree: ${(ppd ?? DEFAULT_PPD).toFixed(4)}`);
console.log(`mean: ${f(p.mean)}`);
console.log(`weighted median: ${f(p.weightedMedian)}`);
console.log(`1st weighted quartile: ${f(p.weightedQuartile1)}`);
console.log(`3rd weighted quartile: ${f(p.weightedQuartile3)}`);
console.log(`min: ${f(p.min)}`);
console.log(`max: ${f(p.max)}`);
if (mapOut) {
  // coloured as the reference tool colours it: the nearest of 256 magma entries
  writeFileSync(mapOut, encodePng(magmaErrorImage(map, ref.width, ref.height)));
  console.log(`error map: ${mapOut}`);
}
