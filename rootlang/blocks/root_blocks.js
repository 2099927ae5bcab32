// @ts-check
/* rootlang blocks: the browser half of rootlang/blocks (the definitions come from Python), an ES
 * module. After Blockly (blockly_compressed.js, blocks_compressed.js, a msg file):
 *     import {install, attach} from "./root_blocks.js";
 *     install(Blockly, definitions);   // definitions: rootlang.blocks.block_definitions()
 *     const workspace = Blockly.inject(div, {toolbox, media: ".../blockly/media/"});
 *     attach(workspace, toolbox);
 *
 * It registers the two mutators the definitions name:
 *   root_values      print, join and procedure calls take any number of values; extraState
 *                    {"values": n} (a call also {"name": "square"}) gives inputs ARG0..ARGn-1;
 *                    the + and − buttons add and remove one.
 *   root_parameters  a procedure's parameters; extraState {"parameters": ["size", ...]} gives
 *                    one text field PARAM0.. each; + and − add and remove one.
 * attach(workspace, toolbox) (after Blockly.inject) fills the Procedures category with a call
 * block for each `to` block in the workspace.
 * Everything else about the blocks (words, menus, colours, the toolbox) is generated in Python
 * from the language description, so it is never written twice.
 */

/** @typedef {typeof import("blockly")} BlocklyModule */
/** @typedef {import("blockly").BlockSvg} BlockSvg */
/** @typedef {import("blockly").WorkspaceSvg} WorkspaceSvg */
/** @typedef {import("blockly").utils.toolbox.FlyoutItemInfo} FlyoutItemInfo */
/**
 * A block with the root_values mutator: its values (and a call's procedure name).
 * @typedef {BlockSvg & {rootName_: string, rootValues_: number, rootResize_: (count: number) => void}} ValuesBlock
 */
/**
 * A block with the root_parameters mutator.
 * @typedef {BlockSvg & {rootShape_: (names: string[]) => void,
 *                       saveExtraState: () => {parameters: string[]}}} ParametersBlock
 */

const PLUS =
  "data:image/svg+xml;utf8," +
  encodeURIComponent(
    '<svg xmlns="http://www.w3.org/2000/svg" width="16" height="16"><circle cx="8" cy="8" r="7" fill="white" fill-opacity="0.35"/><path d="M8 4v8M4 8h8" stroke="white" stroke-width="2"/></svg>'
  );
const MINUS =
  "data:image/svg+xml;utf8," +
  encodeURIComponent(
    '<svg xmlns="http://www.w3.org/2000/svg" width="16" height="16"><circle cx="8" cy="8" r="7" fill="white" fill-opacity="0.35"/><path d="M4 8h8" stroke="white" stroke-width="2"/></svg>'
  );

/** The + and − buttons' size in workspace units (`install` may make them bigger, for fingers). */
let buttonSize = 16;

/**
 * @param {BlocklyModule} Blockly
 * @param {string} src
 * @param {string} label
 * @param {() => void} onClick
 */
function button(Blockly, src, label, onClick) {
  return new Blockly.FieldImage(src, buttonSize, buttonSize, label, onClick);
}

/**
 * One undo step, and an event Blockly's listeners (the studio's sync) see as a change.
 * @param {BlocklyModule} Blockly
 * @param {BlockSvg} block
 * @param {() => void} change
 */
function inGroup(Blockly, block, change) {
  const before = block.saveExtraState?.();
  Blockly.Events.setGroup(true);
  change();
  const after = block.saveExtraState?.();
  const BlockChange = Blockly.Events.get(Blockly.Events.BLOCK_CHANGE);
  Blockly.Events.fire(new BlockChange(block, "mutation", null, JSON.stringify(before), JSON.stringify(after)));
  Blockly.Events.setGroup(false);
}

/** @param {BlocklyModule} Blockly */
function valuesMutator(Blockly) {
  return {
    /** @this {ValuesBlock} */
    saveExtraState: function () {
      /** @type {{name?: string, values?: number}} */
      const state = {};
      if (this.rootName_) state.name = this.rootName_;
      state.values = this.rootValues_ || 0;
      return state;
    },
    /**
     * A new block, or undo and redo: the slots are added or taken away at the end only, so
     * the values plugged into the others stay where they are.
     * @this {ValuesBlock}
     * @param {{name?: unknown, values?: unknown} | null} state
     */
    loadExtraState: function (state) {
      const name = state && state.name ? String(state.name) : "";
      if (name !== (this.rootName_ || "") || !this.getInput("ROOT_TAIL")) {
        this.rootName_ = name;
        if (this.getInput("ROOT_NAME")) this.removeInput("ROOT_NAME");
        if (name) {
          this.appendDummyInput("ROOT_NAME").appendField(name);
          if (this.inputList.length > 1) this.moveInputBefore("ROOT_NAME", this.inputList[0].name);
        }
      }
      this.rootResize_(state && Number.isInteger(state.values) ? Math.max(0, Number(state.values)) : 0);
    },
    /**
     * Exactly `count` value slots, changed at the end only; then the + and − buttons.
     * @this {ValuesBlock}
     * @param {number} count
     */
    rootResize_: function (count) {
      if (this.getInput("ROOT_TAIL")) this.removeInput("ROOT_TAIL");
      let now = 0;
      while (this.getInput("ARG" + now)) now++;
      for (; now < count; now++) {
        const input = this.appendValueInput("ARG" + now);
        if (now > 0) input.appendField(",");
      }
      for (; now > count; now--) {
        const last = /** @type {import("blockly").Input} */ (this.getInput("ARG" + (now - 1)));
        const child = last.connection && last.connection.targetBlock();
        // a value the child made is bumped out (kept, loose); a shadow can't lie loose: it goes
        if (child && child.isShadow()) child.dispose(false);
        else if (child) child.unplug();
        this.removeInput("ARG" + (now - 1));
      }
      this.rootValues_ = count;
      const tail = this.appendDummyInput("ROOT_TAIL");
      const block = this;
      tail.appendField(button(Blockly, PLUS, "add a value", function () {
        inGroup(Blockly, block, function () { block.rootResize_(block.rootValues_ + 1); });
      }));
      if (count > 0) {
        tail.appendField(button(Blockly, MINUS, "remove the last value", function () {
          inGroup(Blockly, block, function () { block.rootResize_(block.rootValues_ - 1); });
        }));
      }
    },
  };
}

/** @param {BlocklyModule} Blockly */
function parametersMutator(Blockly) {
  return {
    /** @this {ParametersBlock} */
    saveExtraState: function () {
      const names = [];
      for (let i = 0; this.getField("PARAM" + i); i++) names.push(String(this.getFieldValue("PARAM" + i)));
      return {parameters: names};
    },
    /**
     * @this {ParametersBlock}
     * @param {{parameters?: unknown} | null} state
     */
    loadExtraState: function (state) {
      const names = state && Array.isArray(state.parameters) ? state.parameters.map(String) : [];
      this.rootShape_(names);
    },
    /**
     * @this {ParametersBlock}
     * @param {string[]} names
     */
    rootShape_: function (names) {
      if (this.getInput("ROOT_PARAMETERS")) this.removeInput("ROOT_PARAMETERS");
      const input = this.appendDummyInput("ROOT_PARAMETERS");
      names.forEach(function (name, i) {
        if (i > 0) input.appendField(",");
        input.appendField(new Blockly.FieldTextInput(name), "PARAM" + i);
      });
      const block = this;
      input.appendField(
        button(Blockly, PLUS, "add a parameter", function () {
          inGroup(Blockly, block, function () {
            const now = block.saveExtraState().parameters;
            now.push("value" + (now.length + 1));
            block.rootShape_(now);
          });
        })
      );
      if (names.length > 0) {
        input.appendField(
          button(Blockly, MINUS, "remove the last parameter", function () {
            inGroup(Blockly, block, function () {
              const now = block.saveExtraState().parameters;
              now.pop();
              block.rootShape_(now);
            });
          })
        );
      }
      // The parameters come right after the name, before the body.
      if (this.getInput("BODY")) this.moveInputBefore("ROOT_PARAMETERS", "BODY");
    },
  };
}

/**
 * Registers the mutators (once) and defines the blocks.
 * @param {BlocklyModule} Blockly
 * @param {Record<string, unknown>[]} definitions
 * @param {number} [buttons] the + and − buttons' size in workspace units (default 16)
 */
export function install(Blockly, definitions, buttons) {
  if (buttons) buttonSize = buttons;
  if (!Blockly.Extensions.isRegistered("root_values")) {
    Blockly.Extensions.registerMutator("root_values", valuesMutator(Blockly));
    Blockly.Extensions.registerMutator("root_parameters", parametersMutator(Blockly));
  }
  // (ours take the place of Blockly's own, without its warning: its `if`, in the Control colour)
  for (const definition of definitions) delete Blockly.Blocks[String(definition.type)];
  Blockly.common.defineBlocksWithJsonArray(definitions);
}

/**
 * The Procedures category: its blocks from the toolbox, then a call (as a command and as a
 * value) for each `to` block in the workspace, with as many values as it has parameters.
 * @param {WorkspaceSvg} workspace
 * @param {import("blockly").utils.toolbox.ToolboxInfo} toolbox
 */
export function attach(workspace, toolbox) {
  // (the category rootlang.blocks.toolbox() names ROOT_PROCEDURES: custom, with fixed contents)
  const categories = /** @type {{custom?: string, contents?: FlyoutItemInfo[]}[]} */ (toolbox.contents || []);
  const category = categories.find(item => item.custom === "ROOT_PROCEDURES");
  const fixed = category && category.contents ? category.contents : [];
  workspace.registerToolboxCategoryCallback("ROOT_PROCEDURES", function (ws) {
    /** @type {FlyoutItemInfo[]} */
    const items = fixed.slice();
    ws.getBlocksByType("root_procedure", true).forEach(function (block) {
      const parameters = /** @type {ParametersBlock} */ (block).saveExtraState().parameters;
      const state = {name: block.getFieldValue("NAME"), values: parameters.length};
      items.push({kind: "block", type: "root_call", extraState: state});
      items.push({kind: "block", type: "root_call_value", extraState: state});
    });
    return items;
  });
}
