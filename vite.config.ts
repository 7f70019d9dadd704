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
  },
  worker: { format: 'es' },
  server: { host: '127.0.0.1' },
});
