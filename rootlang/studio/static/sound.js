// @ts-check
// The robot's notes, heard in the page (Web Audio): each note or sweep a run plays, when its
// frame comes, for as long as the robot plays it at the run's speed. Silent when the pupil
// mutes the page (kept in this browser) or the teacher mutes the class.
import {$, state, words} from "./page.js";
import {speaker, showSigned} from "./icons.js";

/** @typedef {import("./messages").NoteJson} NoteJson */

const VOLUME = 0.15;          // a tablet's speaker at full volume is loud in a class of thirty
const FADE_S = 0.01;          // a note starts and ends without a click
const KEPT = "rootlang.muted";

/** @type {AudioContext | null} made at the child's first click (browsers start audio no sooner) */
let context = null;
let pupilMuted = localStorage.getItem(KEPT) === "yes";
let classMuted = false;
let heard = 0;

const muted = () => pupilMuted || classMuted;

/** The page's mute button and what the page tells the tests. */
function show() {
  const button = $("mute");
  const shown = words(muted() ? "sound_off" : "sound_on");   // (its name starts with its words: WCAG 2.5.3)
  showSigned(button, speaker(!muted()), shown, shown + ": " + words(pupilMuted ? "unmute" : "mute"));
  button.setAttribute("aria-pressed", String(pupilMuted));
  button.disabled = classMuted;
  button.title = classMuted ? words("class_muted") : "";
  state.muted = muted() ? "yes" : "no";
  state.classMuted = classMuted ? "yes" : "no";
}

export function setupSound() {
  $("mute").addEventListener("click", () => {
    pupilMuted = !pupilMuted;
    localStorage.setItem(KEPT, pupilMuted ? "yes" : "no");
    show();
  });
  show();
}

/**
 * The teacher muted (or unmuted) the whole class.
 * @param {boolean} on
 */
export function muteClass(on) {
  classMuted = on;
  show();
}

/** On a click of the child's (Run): the audio may start from now on. */
export function wake() {
  if (!context && typeof AudioContext !== "undefined") context = new AudioContext();
  if (context && context.state === "suspended") context.resume().catch(() => {});
}

/**
 * A frame's new notes, played now.
 * @param {NoteJson[]} notes
 * @param {number} speed the run's (0: as fast as it goes, too fast to hear: silent)
 */
export function play(notes, speed) {
  for (const note of notes) {
    if (muted() || speed <= 0 || !context) continue;
    const seconds = note.duration_ms / 1000 / speed, now = context.currentTime;
    const tone = context.createOscillator(), gain = context.createGain();
    tone.type = "triangle";
    tone.frequency.setValueAtTime(note.frequency_hz, now);
    if (note.end_hz !== note.frequency_hz) tone.frequency.linearRampToValueAtTime(note.end_hz, now + seconds);
    gain.gain.setValueAtTime(0, now);
    gain.gain.linearRampToValueAtTime(VOLUME, now + Math.min(FADE_S, seconds / 2));
    gain.gain.setValueAtTime(VOLUME, now + Math.max(seconds - FADE_S, seconds / 2));
    gain.gain.linearRampToValueAtTime(0, now + seconds);
    tone.connect(gain).connect(context.destination);
    tone.start(now);
    tone.stop(now + seconds);
    heard++;
    state.notes = String(heard);
    state.lastNote = note.frequency_hz.toFixed(1);
  }
}
