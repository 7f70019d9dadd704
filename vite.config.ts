import { defineConfig } from 'vite';
import react from '@vitejs/plugin-react';

// Relative base: the static build works from any folder of any static host (hash routing).
export default defineConfig({
  base: './',
  plugins: [react()],
  build: {
    target: 'es2022',
    sourcemap: false,
    chunkSizeWarningLimit: 5000,
    rolldownOptions: {
      output: {
        // Heavy libraries get stable, recognisable chunk names (vendor-three-*.js, …) so the
        // bundle budgets and the browser test of what `#/` downloads can name them.
        codeSplitting: {
          groups: [
            { name: 'vendor-three', test: /[\\/]node_modules[\\/]three[\\/]/ },
            { name: 'vendor-plotly', test: /[\\/]node_modules[\\/]plotly\.js-cartesian-dist-min[\\/]/ },
            { name: 'vendor-mathjs', test: /[\\/]node_modules[\\/](mathjs|decimal\.js|complex\.js|fraction\.js|typed-function|javascript-natural-sort|seedrandom|escape-latex|tiny-emitter)[\\/]/ },
            { name: 'vendor-katex', test: /[\\/]node_modules[\\/]katex[\\/]/ },
            // each scene folder is one chunk, named after the scene (scene-texture-*.js, …)
            { debugName: 'scenes', name: (id: string) => /[\\/]src[\\/]scenes[\\/]([a-z0-9-]+)[\\/]/.exec(id)?.[1]?.replace(/^/, 'scene-') ?? null },
          ],
        },
      },
    },
  },
  worker: { format: 'es' },
  server: { host: '127.0.0.1' },
});
