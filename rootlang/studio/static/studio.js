// @ts-check
// rootlang studio: blocks and text side by side (the conversion is the server's, in Python),
// runs streamed from the real runtime and simulator over a WebSocket, and the class folder.
// This module starts the page; the others are its parts (see docs/studio.md).
import {$, state, setWords, say, words, translatePage, chooseLanguage, inPageLanguage} from "./page.js";
import {editor, colourWords} from "./editor.js";
import {setupBlocks, loadBlocklyWords} from "./blocks.js";
import {textEdited, blocksEdited} from "./sync.js";
import {refreshPrograms, openProgram, save, saveFailed, newProgram, renameProgram, keepMine,
        setEditable} from "./files.js";
import {claimTab} from "./drafts.js";
import {setupUndo} from "./undo.js";
import {run, stop, findRobots, robotChosen, stimulate, setupRobots, showStart} from "./runs.js";
import {knowLightColours} from "./narrator.js";
import {setupSound} from "./sound.js";
import {setupPanes} from "./panes.js";
import {setupKeyboard} from "./keyboard.js";
import {setupLevels} from "./levels.js";

/** @param {unknown} error */
const sayError = error => say(String(/** @type {Error} */ (error).message), true);

/**
 * The page opens again while the studio is out of reach (sw.js). Only a page served securely
 * may have a service worker: on this computer, or a class's with --https (a class over plain
 * http goes without; docs/studio.md, "Offline").
 */
function keepForOffline() {
  if (!("serviceWorker" in navigator) || !isSecureContext) return;
  navigator.serviceWorker.addEventListener("message", event => {
    if (event.data && typeof event.data.kept === "number") state.offline = "ready";
  });
  // (a page it looked after from the start: its answers were kept as they came)
  const lookedAfter = navigator.serviceWorker.controller !== null;
  navigator.serviceWorker.register("/sw.js")
    .then(() => navigator.serviceWorker.ready)
    .then(registration => {
      if (lookedAfter) { state.offline = "ready"; return; }
      registration.active?.postMessage({keep: [location.href,
        ...performance.getEntriesByType("resource").map(entry => entry.name)
          .flatMap(address => address.includes("/api/") ? [address, inPageLanguage(address)] : [address])]});
    })
    .catch(() => { state.offline = "no"; });   // (the page works as before, online only)
}

async function start() {
  editor.on("changes", textEdited);
  const saveKey = () => { save().catch(saveFailed); };
  editor.setOption("extraKeys", {"Ctrl-S": saveKey, "Cmd-S": saveKey});
  setupKeyboard();   // (Tab indents; Esc then Tab leaves the text)
  await claimTab();   // (before any draft is kept or looked for)
  const setup = await refreshPrograms();
  setWords(setup.strings);
  translatePage(setup);
  colourWords(setup.language, setup.syntax);
  knowLightColours(setup.light_colours);
  $("language").addEventListener("change", chooseLanguage);
  $("world").replaceChildren(new Option(words("its_own"), ""),
                             ...setup.worlds.map(name => new Option(name, name)));
  await loadBlocklyWords(setup.blockly_messages);
  setupBlocks(setup.blocks, blocksEdited);
  setupUndo();   // (one undo history for both panes)
  setEditable(false);   // (until a program opens)
  setupLevels(setup.blocks, Number(new URLSearchParams(location.search).get("level") || 2));
  $("program").addEventListener("change", () => openProgram($("program").value));
  $("new").addEventListener("click", newProgram);
  $("rename").addEventListener("click", renameProgram);
  $("save").addEventListener("click", () => save().catch(saveFailed));
  $("keep-mine").addEventListener("click", keepMine);
  $("run").addEventListener("click", run);
  $("world").addEventListener("change", showStart);
  setupSound();
  setupPanes();
  $("scan").addEventListener("click", findRobots);
  $("robot").addEventListener("change", robotChosen);
  $("stop").addEventListener("click", stop);
  setupRobots(setup.bluetooth);
  document.querySelectorAll("[data-touch]").forEach(button => button.addEventListener("click",
    () => stimulate({action: "touch", sensors: [/** @type {HTMLElement} */ (button).dataset.touch || ""]})));
  document.querySelectorAll("[data-bump]").forEach(button => button.addEventListener("click",
    () => stimulate({action: "bump", sensors: (/** @type {HTMLElement} */ (button).dataset.bump || "").split(" ")})));
  $("robot-buttons").querySelector("[data-nose]").addEventListener("click", () => stimulate({action: "nose"}));
  const wanted = new URLSearchParams(location.search).get("open");
  const first = wanted || (setup.programs[0] && setup.programs[0].name);
  // (a link to a program the folder does not have makes it; with none open, nothing can be
  // changed, and the status line says what to do)
  if (first) await openProgram(first, {make: first === wanted}).catch(sayError);
  else say(words("no_programs"));
  state.ready = "yes";
  keepForOffline();   // (its questions as the page asks them now, in its language)
}

start().catch(sayError);
