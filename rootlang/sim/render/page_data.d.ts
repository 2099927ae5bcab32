// Made by `python -m rootlang.studio.messages` from the Python types: do not edit.

/** Text at a point (world mm), ``size`` mm high. */
export interface LabelShape {
  k: "label";
  at: number[];
  text: string;
  size: number;
  color: string;
  anchor: string;
}

/** A circle: centre ``c`` [x, y] and radius ``r`` (mm). */
export interface CircleShape {
  f: string | null;
  s: string | null;
  w: number;
  o?: number;
  k: "circle";
  c: number[];
  r: number;
}

/** A polygon or a polyline: ``p`` flat [x0, y0, x1, y1, ...] mm. */
export interface PathShape {
  f: string | null;
  s: string | null;
  w: number;
  o?: number;
  t?: number[];
  k: "polygon" | "line";
  p: number[];
}

/** Where the eraser went: what ink is under it is wiped. */
export interface EraseInk {
  k: "erase";
  p: number[];
  t: number[];
  w: number;
}

export interface LedState {
  color: string;
  mode: string;
}

/** The robot's poses, column by column: time (s), x, y (mm), heading (deg, anticlockwise from +x) and the light (an index into ``leds``). */
export interface Frames {
  t: number[];
  x: number[];
  y: number[];
  h: number[];
  led: number[];
}

/** A run as the replay page (and the studio's stage) draws it: world mm, y up. */
export interface PageData {
  view: number[];
  background: string;
  below: (LabelShape | CircleShape | PathShape)[];
  ink: (PathShape | EraseInk)[];
  path: PathShape | null;
  overlay: (LabelShape | CircleShape | PathShape)[];
  robot: (LabelShape | CircleShape | PathShape)[];
  led: number;
  leds: LedState[];
  frames: Frames;
  events: [number, string, string, number][];
  said: [number, string][];
  title: string;
  subtitle: string;
}

export type Shape = LabelShape | CircleShape | PathShape;
