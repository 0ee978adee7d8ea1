// Lint: typescript-eslint's recommended rules, plus the type-aware ones that catch what the
// compiler lets through: assertions that assert nothing and promises nobody waits for.
import js from '@eslint/js';
import tseslint from 'typescript-eslint';

export default tseslint.config(
  { ignores: ['dist/**', 'node_modules/**', 'chunks/**', 'client/public/**'] },
  js.configs.recommended,
  ...tseslint.configs.recommended,
  {
    files: ['**/*.ts'],
    languageOptions: {
      parserOptions: {
        project: ['./tsconfig.json', './client/tsconfig.json', './client/tsconfig.sw.json'],
        tsconfigRootDir: import.meta.dirname,
      },
    },
    rules: {
      '@typescript-eslint/no-unnecessary-type-assertion': 'error',
      '@typescript-eslint/no-floating-promises': 'error',
      '@typescript-eslint/no-unused-vars': ['error', { argsIgnorePattern: '^_', varsIgnorePattern: '^_' }],
    },
  },
  // The imports go one way: format <- preprocess, format <- client. Neither side reaches into
  // the other, and format/ depends on neither.
  {
    files: ['format/**/*.ts'],
    rules: { 'no-restricted-imports': ['error', { patterns: [{ group: ['**/preprocess/**', '**/client/**', '**/server/**'], message: 'format/ stands alone: preprocess and client import it, not the other way.' }] }] },
  },
  {
    files: ['preprocess/**/*.ts'],
    rules: { 'no-restricted-imports': ['error', { patterns: [{ group: ['**/client/**'], message: 'Shared code belongs in format/.' }] }] },
  },
  {
    files: ['client/**/*.ts'],
    rules: { 'no-restricted-imports': ['error', { patterns: [{ group: ['**/preprocess/**', '**/server/**'], message: 'Shared code belongs in format/.' }] }] },
  },
  {
    // node:test's test() and describe() return promises the runner itself waits for.
    files: ['**/*.test.ts', 'e2e/**/*.ts', 'server/test/**/*.ts'],
    rules: { '@typescript-eslint/no-floating-promises': 'off' },
  },
  {
    files: ['**/*.js'],
    languageOptions: { globals: { process: 'readonly', console: 'readonly', URL: 'readonly' } },
  },
);
