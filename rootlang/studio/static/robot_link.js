// @ts-check
// The pupil's own robot over Web Bluetooth: this page is the robot's link, the runtime stays in
// the studio. Packets come from the run over the WebSocket (`robot_packet`), are written to the
// robot's UART RX one at a time and acknowledged (`robot_written`); the robot's TX
// notifications go back (`robot_notify`). The page also keeps the robot safe on its own: it
// sends Stop and Reset, then ends the link, whenever its run can no longer steer it (see
// `safeStop` and docs/studio.md). The packets it sends on its own (Stop and Reset, the hello
// light and chirp) come from the studio, made from the protocol's table: no packet is built here.

/** @typedef {import("./messages").RobotLinkMessage} RobotLinkMessage */
/** @typedef {import("./messages").RobotPacketMessage} RobotPacketMessage */
/** @typedef {import("./messages").BluetoothProfile} BluetoothProfile */
/** @typedef {import("./messages").FromPage} FromPage */
/** @typedef {import("./messages").ToPage} ToPage */

/**
 * Why this browser can't link a robot: "" (it can), "insecure" (Web Bluetooth exists only on
 * https or on this computer), "browser" (Firefox, Safari, iPads: no Web Bluetooth at all).
 * @returns {"" | "insecure" | "browser"}
 */
export function missingBluetooth() {
  // Chrome hides navigator.bluetooth outside a secure context; other browsers never have it.
  const chromium = /Chrome\/|Chromium\//.test(navigator.userAgent);  // (not iOS: never there)
  if ("bluetooth" in navigator) return "";
  return !window.isSecureContext && chromium ? "insecure" : "browser";
}

/**
 * @typedef {object} LinkHost What the page gives its link
 * @property {(message: FromPage) => boolean} send  to the studio, over the WebSocket (false: it is not open)
 * @property {(event: string, detail?: Record<string, string>) => void} told  what happened, for the page to show
 * @property {(error: unknown) => string} problem  a Bluetooth failure in the child's words
 */

/** @typedef {import("./messages").RobotStoppedMessage} RobotStoppedMessage */

/** The link of this page to its robot, once one is chosen (also the seam's target). */
/** @type {RobotLink | null} */
let current = null;

export class RobotLink {
  /**
   * @param {BluetoothProfile} profile  the robots' UUIDs, from the studio's setup
   * @param {LinkHost} host
   */
  constructor(profile, host) {
    this.profile = profile;
    this.host = host;
    /** @type {BluetoothDevice | null} */
    this.device = null;
    /** @type {BluetoothRemoteGATTCharacteristic | null} */
    this.rx = null;
    /** @type {BluetoothRemoteGATTCharacteristic | null} */
    this.tx = null;
    /** @type {RobotLinkMessage | null} the studio's answer to our robot: its packets and rules */
    this.rules = null;
    /** @type {RobotPacketMessage[]} packets waiting their turn (GATT does one write at a time) */
    this.queue = [];
    this.writing = false;
    this.running = false;     // a run on this robot goes on
    this.moving = false;      // the last motion packet set it moving
    this.stopping = false;    // a safe stop is under way: nothing else is written
    this.lastHeard = performance.now();
    /** @type {number | null} */
    this.hiddenSince = null;
    /** @type {number | null} */
    this.stopDeadline = null;
    /** @type {string[]} why the page stopped the robot itself, for the tests and the page */
    this.safeStops = [];
    /** @type {RobotStoppedMessage | null} the studio is yet to hear that the page stopped it */
    this.untold = null;
    /** @type {number[]} how long each write to the robot took (ms): the benchmark's */
    this.writeTimes = [];
    this.onNotification = this.onNotification.bind(this);
    this.onDisconnected = this.onDisconnected.bind(this);
    this.watch = window.setInterval(() => this.check(), 250);
    document.addEventListener("visibilitychange", () => {
      this.hiddenSince = document.hidden ? performance.now() : null;
    });
    // Closed or left: write Stop and Reset while the page still can (if the write is lost,
    // the link ends with the page and a Root stops when its host goes).
    window.addEventListener("pagehide", () => this.safeStop("pagehide"));
    current = this;
  }

  get name() { return this.device ? this.device.name || "" : ""; }

  get linked() { return Boolean(this.device && this.device.gatt && this.device.gatt.connected && this.rx); }

  /** "Connect a robot": the browser's chooser (a click is needed), then the link. */
  async choose() {
    const p = this.profile;
    const device = await navigator.bluetooth.requestDevice({
      filters: [{services: [p.identifier]}, {manufacturerData: [{companyIdentifier: p.company}]}],
      optionalServices: [p.uart, p.information],
    });
    if (this.device && this.device !== device) await this.unlink();
    this.device = device;
    device.addEventListener("gattserverdisconnected", this.onDisconnected);
    const information = await this.open();
    this.host.send({type: "robot_linked", name: device.name || "", ...information});
  }

  /** Connects (again: the link ends after every run) and subscribes to the robot's packets. */
  async open() {
    const device = /** @type {BluetoothDevice} */ (this.device);
    const gatt = /** @type {BluetoothRemoteGATTServer} */ (device.gatt);
    const server = await gatt.connect();
    const uart = await server.getPrimaryService(this.profile.uart);
    this.rx = await uart.getCharacteristic(this.profile.rx);
    this.tx = await uart.getCharacteristic(this.profile.tx);
    this.tx.addEventListener("characteristicvaluechanged", this.onNotification);
    await this.tx.startNotifications();
    this.stopping = false;
    this.host.told("connection", {connected: "yes"});
    /** @type {{serial: string, firmware: string, hardware: string}} */
    const information = {serial: "", firmware: "", hardware: ""};
    try {
      const service = await server.getPrimaryService(this.profile.information);
      for (const key of /** @type {const} */ (["serial", "firmware", "hardware"])) {
        const value = await service.getCharacteristic(this.profile[key]).then(c => c.readValue()).catch(() => null);
        if (value) information[key] = new TextDecoder().decode(value).replace(/\0+$/, "").trim();
      }
    } catch { /* no Device Information: the studio takes the usual Root */ }
    return information;
  }

  /** Before a run: linked again if the last run ended the link. */
  async ready() {
    if (!this.device) throw new Error("no robot");
    if (!this.linked) await this.open();
    this.running = true; this.moving = false; this.stopDeadline = null;
    this.lastHeard = performance.now();
  }

  async unlink() {
    const device = this.device;
    if (!device) return;
    await this.safeStop("unlinked");
    device.removeEventListener("gattserverdisconnected", this.onDisconnected);
    this.device = null; this.rules = null;
    this.host.send({type: "robot_unlinked"});
  }

  /**
   * Every message from the studio: it is alive; some are for the link.
   * @param {ToPage} message
   */
  fromStudio(message) {
    this.lastHeard = performance.now();
    if (message.type === "robot_link") {
      this.rules = message;
      this.host.told("linked", {name: this.name, robot: message.robot});
      this.hello();
    } else if (message.type === "robot_packet") {
      if (message.moves !== null) this.moving = message.moves;
      this.queue.push(message);
      void this.drain();
    } else if (message.type === "ended" && this.running) {
      this.running = false;
      this.safeStop("ended");
    } else if (message.type === "error" && this.running && message.code !== "E810") {
      this.running = false;   // the run did not start (or could not go on)
    }
  }

  /** The WebSocket to the studio dropped: nobody steers the robot any more. */
  studioLost() {
    if (this.running || this.moving) this.safeStop("socket");
    this.running = false;
  }

  /** The studio hears that the page stopped the robot, and why: at once if the socket is
   * open (also when the studio has gone quiet: it reads it when it wakes), else when it is
   * back (`studioBack`). */
  tellStudio() {
    if (this.untold && this.host.send(this.untold)) this.untold = null;
  }

  /** The WebSocket to the studio is open again. */
  studioBack() { this.tellStudio(); }

  /** The page's Stop: the run's `when stopped` scripts get their time, then the robot stops. */
  stopPressed() {
    if (!this.running || !this.rules) return;
    this.stopDeadline = performance.now() + this.rules.stop_grace_s * 1000;
  }

  /** Say "here I am": a green spinning light and a rising chirp, the one robot of thirty that
   * does it right after this page linked it. */
  async hello() {
    if (!this.rules || !this.rx) return;
    for (const packet of this.rules.hello) await this.write(packet).catch(() => undefined);
  }

  async drain() {
    if (this.writing) return;
    this.writing = true;
    try {
      while (this.queue.length) {
        const message = /** @type {RobotPacketMessage} */ (this.queue.shift());
        if (this.stopping) {   // the page has stopped the robot: the run hears so at once
          this.host.send({type: "robot_written", n: message.n, error: "stopped by the page"});
          continue;
        }
        try {
          await this.write(message.data);
          this.host.send({type: "robot_written", n: message.n});
        } catch (error) {
          this.host.send({type: "robot_written", n: message.n, error: this.host.problem(error)});
        }
      }
    } finally {
      this.writing = false;
    }
  }

  /** @param {string} hex  one 20-byte packet */
  async write(hex) {
    if (!this.rx) throw new Error("not linked");
    const bytes = new Uint8Array(hex.match(/../g)?.map(pair => parseInt(pair, 16)) ?? []);
    const started = performance.now();
    await this.rx.writeValueWithResponse(bytes);
    if (this.writeTimes.length < 100000) this.writeTimes.push(performance.now() - started);
  }

  /**
   * Stop and Reset, then end the link: the page's own safety, whatever the studio does.
   * @param {string} why
   */
  async safeStop(why) {
    if (this.stopping || !this.rules || !this.linked) return;
    this.stopping = true; this.moving = false; this.stopDeadline = null;
    this.safeStops.push(why);
    if (this.running && why !== "ended" && why !== "unlinked") {   // the run's end says why
      this.untold = {type: "robot_stopped", why: /** @type {RobotStoppedMessage["why"]} */ (why)};
      this.tellStudio();
    }
    if (why !== "ended" && why !== "unlinked") this.host.told("safe_stop", {why: why});
    try {
      // (wait for a write the run left under way: GATT takes one operation at a time)
      for (let i = 0; this.writing && i < 20; i++) await new Promise(resolve => setTimeout(resolve, 10));
      await this.write(this.rules.stop);
    } catch { /* the link is already gone: a Root stops when its host goes */ }
    if (this.device && this.device.gatt && this.device.gatt.connected) this.device.gatt.disconnect();
    this.rx = null; this.tx = null;
    this.host.told("connection", {connected: "no"});
  }

  /** Every 250 ms (once a second in a hidden tab: browsers slow hidden pages' timers). */
  check() {
    if (!this.rules) return;
    const now = performance.now();
    if (this.running && this.moving && now - this.lastHeard > this.rules.silence_s * 1000) {
      this.safeStop("silence");
    } else if (this.running && this.hiddenSince !== null && now - this.hiddenSince > this.rules.hidden_s * 1000) {
      this.safeStop("hidden");
    } else if (this.stopDeadline !== null && now > this.stopDeadline) {
      this.safeStop("stop");
    }
  }

  /** @param {Event} event  the robot's TX notification: one packet */
  onNotification(event) {
    const value = /** @type {BluetoothRemoteGATTCharacteristic} */ (event.target).value;
    if (value) this.relay(value);
  }

  /** @param {DataView} value */
  relay(value) {
    const bytes = new Uint8Array(value.buffer, value.byteOffset, value.byteLength);
    const hex = Array.from(bytes, byte => byte.toString(16).padStart(2, "0")).join("");
    this.host.send({type: "robot_notify", data: hex});
  }

  onDisconnected() {
    this.rx = null; this.tx = null;
    this.host.told("connection", {connected: "no"});
    if (this.stopping) return;   // we ended it
    if (this.running) this.host.send({type: "robot_lost"});
    this.running = false; this.moving = false;
    this.host.told("lost", {name: this.name});
  }
}

/**
 * THE TEST SEAM (the only one): Chromium's Bluetooth emulation can't send a notification to the
 * page, so the tests' virtual robot hands its packets here; they take the path a real
 * `characteristicvaluechanged` event takes from here on. Nothing in the page calls it.
 * @param {string} hex  one packet from the robot
 */
export function emulatedNotification(hex) {
  if (!current || !current.tx) return false;
  const bytes = new Uint8Array(hex.match(/../g)?.map(pair => parseInt(pair, 16)) ?? []);
  current.relay(new DataView(bytes.buffer));
  return true;
}

/** The page's link, for the tests to read (`safeStops`, `linked`). */
export function currentLink() { return current; }
