// @ts-check
// The studio's HTTP API, one function per request, typed by the message contract
// (messages.d.ts, written from rootlang/studio/messages.py). Every request carries the page's
// language, so what the server says comes back in it.
import {inPageLanguage, words} from "./page.js";

/** @typedef {import("./messages").ErrorsReply} ErrorsReply */
/** @typedef {import("./messages").DiagnosticJson} DiagnosticJson */

/** A refused request: the server's diagnostics (in the page's language), with their codes. */
export class Refused extends Error {
  /**
   * @param {DiagnosticJson[]} errors
   * @param {string} fallback
   */
  constructor(errors, fallback) {
    super(errors.map(e => e.message).join("\n") || fallback);
    this.errors = errors;
  }
}

/** No answer from the studio (stopped, restarting, the network gone): said in the child's words
 * and the page's language, never the browser's "Failed to fetch". */
export class OutOfTouch extends Error {
  constructor() { super(words("out_of_touch")); this.name = "OutOfTouch"; }
}

/**
 * @template T
 * @param {string} method
 * @param {string} path
 * @param {object} [body]
 * @returns {Promise<T>}
 */
async function request(method, path, body) {
  let response, data;
  try {
    response = await fetch(inPageLanguage(path), {
      method: method, headers: body ? {"Content-Type": "application/json"} : {},
      body: body ? JSON.stringify(body) : undefined,
    });
    data = await response.json();
  } catch {   // no answer ("Failed to fetch"), or not the studio's (a proxy's error page)
    throw new OutOfTouch();
  }
  if (!response.ok) throw new Refused(/** @type {ErrorsReply} */ (data).errors || [], response.statusText);
  return data;
}

/** @returns {Promise<import("./messages").SetupReply>} */
export const setup = () => request("GET", "/api/setup");

/**
 * @param {string} name
 * @returns {Promise<import("./messages").ProgramReply>}
 */
export const readProgram = name => request("GET", "/api/program?name=" + encodeURIComponent(name));

/**
 * @param {import("./messages").SaveRequest} body
 * @returns {Promise<import("./messages").SavedReply>}
 */
export const saveProgram = body => request("PUT", "/api/program", body);

/**
 * @param {import("./messages").NameRequest} body
 * @returns {Promise<import("./messages").SavedReply>}
 */
export const createProgram = body => request("POST", "/api/program", body);

/**
 * @param {import("./messages").RenameRequest} body
 * @returns {Promise<import("./messages").RenamedReply>}
 */
export const renameProgram = body => request("POST", "/api/rename", body);

/**
 * Text to blocks.
 * @param {import("./messages").TextRequest} body
 * @returns {Promise<import("./messages").BlocksReply>}
 */
export const toBlocks = body => request("POST", "/api/blocks", {level: shownLevel, ...body});

/**
 * Blocks to text.
 * @param {import("./messages").WorkspaceRequest} body
 * @returns {Promise<import("./messages").TextReply>}
 */
export const toText = body => request("POST", "/api/text", {level: shownLevel, ...body});

/** The level the page shows (levels.js): the server's blocks are that level's. */
let shownLevel = 2;
/** @param {number} level */
export function setLevel(level) { shownLevel = level; }

/**
 * The world and the robot where a run would start (the stage before any run).
 * @param {import("./messages").StageRequest} body
 * @returns {Promise<import("./messages").StageData>}
 */
export const stage = body => request("POST", "/api/stage", body);

/** @returns {Promise<import("./messages").RobotsReply>} */
export const robots = () => request("GET", "/api/robots");

// --- a class: the pupil's name, Check, and the teacher's page ----------------------------------

/** @returns {Promise<import("./messages").WhoReply>} */
export const who = () => request("GET", "/api/pupil");

/**
 * @param {import("./messages").PupilRequest} body
 * @returns {Promise<import("./messages").PupilReply>}
 */
export const join = body => request("POST", "/api/pupil", body);

/**
 * @param {import("./messages").CheckRequest} body
 * @returns {Promise<import("./messages").CheckReply>}
 */
export const check = body => request("POST", "/api/check", body);

/** @returns {Promise<import("./messages").AdventuresReply>} */
export const adventures = () => request("GET", "/api/adventures");

/**
 * @param {import("./messages").AdventureRequest} body
 * @returns {Promise<import("./messages").AdventureReply>}
 */
export const startAdventure = body => request("POST", "/api/adventure", body);

/**
 * @param {import("./messages").LoginRequest} body
 * @returns {Promise<import("./messages").LoginReply>}
 */
export const teacherLogin = body => request("POST", "/api/teacher/login", body);

/** @returns {Promise<import("./messages").TeacherSetupReply>} */
export const teacherSetup = () => request("GET", "/api/teacher/setup");

/** @returns {Promise<import("./messages").StopAllReply>} */
export const stopAll = () => request("POST", "/api/teacher/stop");

/**
 * @param {import("./messages").NoticeRequest} body
 * @returns {Promise<import("./messages").NoticeReply>}
 */
export const tellClass = body => request("POST", "/api/teacher/notice", body);

/**
 * @param {import("./messages").LockRequest} body
 * @returns {Promise<import("./messages").LockRequest>}
 */
export const lockClass = body => request("POST", "/api/teacher/lock", body);

/**
 * @param {import("./messages").MuteRequest} body
 * @returns {Promise<import("./messages").MuteRequest>}
 */
export const muteClass = body => request("POST", "/api/teacher/mute", body);

/**
 * The level for the class, or for one pupil (teacher).
 * @param {import("./messages").LevelRequest} body
 * @returns {Promise<import("./messages").LevelRequest>}
 */
export const chooseLevel = body => request("POST", "/api/teacher/level", body);

/**
 * @param {import("./messages").ClassCheckRequest} body
 * @returns {Promise<import("./messages").ClassCheckReply>}
 */
export const checkClass = body => request("POST", "/api/teacher/check", body);
