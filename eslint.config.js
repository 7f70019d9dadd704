// ESLint: typescript-eslint's recommended rules, React hooks, and the layer rule
// (eslint-rules/layers.js). `npm run lint` runs it with --max-warnings 0 (npm test does too).
import js from '@eslint/js';
import tseslint from 'typescript-eslint';
import reactHooks from 'eslint-plugin-react-hooks';
import globals from 'globals';
import layers from './eslint-rules/layers.js';

export default tseslint.config(
  {
    ignores: [
      'dist/**',
      'dist-single/**',
      'dist-lms/**',
      'dist-fuzz/**',
      'node_modules/**',
      'bench/**/*.json',
      'public/**',
      'coverage/**',
    ],
  },
  js.configs.recommended,
  ...tseslint.configs.recommended,
  {
    files: ['**/*.{ts,tsx}'],
    plugins: { 'react-hooks': reactHooks, local: { rules: { layers } } },
    languageOptions: { globals: { ...globals.browser, ...globals.worker } },
    rules: {
      // the two classic hook rules (the React Compiler's rules are not adopted: no compiler here)
      'react-hooks/rules-of-hooks': 'error',
      'react-hooks/exhaustive-deps': 'warn',
      'local/layers': 'error',
    },
  },
  {
    rules: {
      '@typescript-eslint/no-unused-vars': [
        'warn',
        {
          argsIgnorePattern: '^_',
          varsIgnorePattern: '^_',
          destructuredArrayIgnorePattern: '^_',
          ignoreRestSiblings: true,
        },
      ],
    },
  },
  {
    // Tests read untyped data (parsed XML and JSON of LMS packages, xAPI statements) and drive
    // mathjs' BigNumber instance, whose typings do not follow it through generic calls.
    files: ['tests/**'],
    rules: { '@typescript-eslint/no-explicit-any': 'off' },
  },
  {
    files: ['**/*.{js,mjs}', 'scripts/**', 'vite.config.ts', 'playwright.config.ts', 'vitest.config.ts'],
    languageOptions: { globals: { ...globals.node, ...globals.browser } },
  },
);
