// @ts-check
// The pupil's own robot, linked by this page over Web Bluetooth (robot_link.js): the Connect a
// robot button, what the page says about the link in its language, and "my robot" under Run on.
import {$, state, words, say} from "./page.js";
import {RobotLink, missingBluetooth} from "./robot_link.js";

/** @typedef {import("./messages").BluetoothProfile} BluetoothProfile */
/** @typedef {import("./messages").FromPage} FromPage */

/** The Run on choice that is this page's own robot. */
export const PAGE_ROBOT = "page";

/** @type {RobotLink | null} */
let link = null;

/** This page's link to its robot, once Web Bluetooth is there (null where it is not). */
export function myRobot() { return link; }

/**
 * @typedef {object} RunsSide What the runs give the link
 * @property {(message: FromPage) => boolean} send  to the studio, over the WebSocket (false: not open)
 * @property {() => Promise<unknown>} connect  the WebSocket, open
 * @property {() => void} chosen  the Run on choice changed
 */

/**
 * @param {BluetoothProfile} profile
 * @param {RunsSide} runs
 */
export function setupMyRobot(profile, runs) {
  const missing = missingBluetooth();
  state.bluetooth = missing || "yes";
  if (missing) {   // Firefox, Safari, an iPad, or a page that is not secure: say which
    $("connect-robot").disabled = true;
    $("robot-help").textContent = words("no_bluetooth_" + missing);
    $("robot-help").hidden = false;
    return;
  }
  const made = new RobotLink(profile, {send: runs.send, told: (event, detail) => told(event, detail || {}, runs),
    problem: bluetoothWords});
  link = made;
  $("connect-robot").addEventListener("click", async () => {
    await runs.connect();   // the studio answers a linked robot with its packets and rules
    say(words("connecting"));
    try {
      await made.choose();
    } catch (error) {
      say(bluetoothWords(error), true);
      state.bluetoothProblem = bluetoothProblem(error);
    }
  });
}

/** The browser's Web Bluetooth failures (DOMException names; their messages are Chromium's,
 * in English) by what they mean to a child: the catalogue's key (studio.json) that says it.
 * @param {unknown} error
 * @returns {string}
 */
export function bluetoothProblem(error) {
  const {name, message} = error instanceof Error ? error : {name: "", message: String(error)};
  if (name === "NotFoundError" && /cancel/i.test(message)) return "not_chosen";   // the chooser closed
  if (/adapter|Bluetooth (is )?(not available|unavailable|off)|globally disabled/i.test(message)) return "no_bluetooth_adapter";
  if (name === "SecurityError" || name === "NotAllowedError") return "bluetooth_not_allowed";
  // a robot off, out of range, linked elsewhere, or not answering as a Root: "No Services
  // matching UUID ... found in Device", "Connection failed for unknown reason", "GATT Server is
  // disconnected", "GATT operation failed for unknown reason" ...
  if (["NotFoundError", "NetworkError", "NotSupportedError", "AbortError", "InvalidStateError",
       "TimeoutError", "OperationError"].includes(name)) return "robot_unreachable";
  return "bluetooth_failed";
}

/**
 * A Web Bluetooth failure in the child's words, in the page's language.
 * @param {unknown} error
 */
export function bluetoothWords(error) { return words(bluetoothProblem(error)); }

/**
 * What the link tells the page.
 * @param {string} event
 * @param {Record<string, string>} detail
 * @param {RunsSide} runs
 */
function told(event, detail, runs) {
  if (event === "linked") {
    const chooser = /** @type {HTMLSelectElement} */ ($("robot"));
    let option = Array.from(chooser.options).find(o => o.value === PAGE_ROBOT);
    if (!option) { option = new Option("", PAGE_ROBOT); chooser.add(option, 1); }
    option.textContent = words("my_robot", {name: detail.name});
    chooser.value = PAGE_ROBOT;
    $("robot-name").textContent = detail.name;
    say(words("linked", {name: detail.name}));
    state.robotLinked = detail.name;
    runs.chosen();
  } else if (event === "lost") {
    say(words("link_lost", {name: detail.name}), true);
  } else if (event === "safe_stop") {
    say(words("safe_stop_" + detail.why), true);
  } else if (event === "connection") {
    state.robotConnected = detail.connected;
  }
}
