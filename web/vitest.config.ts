// Unit tests of the pure modules (store, protocol, URL): no DOM, no WebGL (docs/web.md).
import { defineConfig } from 'vitest/config';

export default defineConfig({
  test: {
    include: ['tests/unit/**/*.test.ts'],
    environment: 'node',
  },
});
