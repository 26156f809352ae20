// Vite build of the lab's front end (docs/web.md). `npm run build` writes dist/; `make web` copies it into
// python/pendulab/server/static/, which the Python package serves. `npm run dev` serves the page with hot
// reload and forwards /api and /ws to a `pendulab serve` running on port 8000.
import { defineConfig } from 'vite';

export default defineConfig({
  base: './',
  // the one-file lab's bundle (vite.lab.config.ts, docs/lab.md); none in the server's page
  define: { __PENDULAB_LAB__: 'null' },
  build: {
    outDir: 'dist',
    emptyOutDir: true,
    target: 'es2022',
    chunkSizeWarningLimit: 1000,
  },
  server: {
    fs: { allow: ['..'] }, // protocol/frames.ts imports ../python/pendulab/server/frame.json
    proxy: {
      '/api': 'http://127.0.0.1:8000',
      '/ws': { target: 'ws://127.0.0.1:8000', ws: true },
    },
  },
});
