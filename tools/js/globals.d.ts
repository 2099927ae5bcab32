// The vendored libraries the pages load as classic scripts before their modules: their UMD
// globals are the only globals the modules use (typed by the libraries' own npm declarations).
import type * as BlocklyModule from "blockly";
import type CodeMirrorModule from "codemirror";
import "codemirror/addon/mode/simple";

declare global {
  const Blockly: typeof BlocklyModule;
  const CodeMirror: typeof CodeMirrorModule;
}
