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
        // three.js, Plotly and KaTeX get recognisable chunk names (vendor-three-*.js, …) for the
        // budgets. mathjs is left to the default splitting on purpose: the parse-only expression
        // engine (src/core/expr) must not share a chunk with the full mathjs that the stability
        // panel's BigNumber reference loads.
        // Each scene's lazy chunk is named after it (scene-texture-*.js, …); naming only, so the
        // default splitting (shared modules in shared chunks) is untouched.
        chunkFileNames: (chunk: { facadeModuleId?: string | null }) => {
          const m = /[\\/]src[\\/]scenes[\\/]([a-z0-9-]+)[\\/]index\.ts$/.exec(chunk.facadeModuleId ?? '');
          return m ? `assets/scene-${m[1]}-[hash].js` : 'assets/[name]-[hash].js';
        },
        codeSplitting: {
          groups: [
            { name: 'vendor-three', test: /[\\/]node_modules[\\/]three[\\/]/ },
            { name: 'vendor-plotly', test: /[\\/]node_modules[\\/]plotly\.js-cartesian-dist-min[\\/]/ },
            { name: 'vendor-katex', test: /[\\/]node_modules[\\/]katex[\\/]/ },
          ],
        },
      },
    },
  },
  worker: { format: 'es' },
  server: { host: '127.0.0.1' },
});
