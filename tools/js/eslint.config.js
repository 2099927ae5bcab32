// eslint over the studio's and the replay page's modules (tests/studio/test_javascript.py).
import js from "@eslint/js";
import globals from "globals";

export default [
  {
    files: ["rootlang/studio/static/*.js", "rootlang/sim/render/*.js", "rootlang/blocks/root_blocks.js"],
    ...js.configs.recommended,
    languageOptions: {
      ecmaVersion: 2022,
      sourceType: "module",
      // the browser's, and the vendored libraries' UMD globals: the only globals the modules use
      globals: {...globals.browser, Blockly: "readonly", CodeMirror: "readonly"},
    },
    rules: {
      ...js.configs.recommended.rules,
      "no-var": "error",
      "prefer-const": "error",
      "eqeqeq": ["error", "always"],
      "no-implicit-globals": "error",
      "no-shadow": "error",
      "no-unused-vars": ["error", {args: "after-used"}],
    },
  },
];
