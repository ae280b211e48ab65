// The page's state and its connection to ifar view: every message arrives as one JSON line (the form of
// `ifar echo --json`) on the WebSocket /ws; the model keeps the newest of each kind, the trajectory and the
// force of the last seconds. Pause freezes a copy of the model, so pan and zoom still work on what was
// shown. window.ifarView.summary() tells a test (or a curious engineer at the console) what is drawn.
"use strict";

(function () {
  const scene = new IfarView.Scene(document.getElementById("scene"));
  const panels = new IfarView.Panels();
  const layers = Object.fromEntries(IfarView.Layers.map(([name, , shown]) => [name, shown]));

  function emptyModel() {
    return {
      vehicle: { length_m: 0.9, width_m: 0.7, bumper_width_m: 0.7 },
      pose: null, firstPose: null, poses: 0, trajectory: [],
      graph: null, path: null, goal: null, exec: null, planner: null, affordance: null, force: null,
      forceHistory: [], truth: null, blockedPassages: [], heartbeats: {}, channels: null, messages: 0,
      lcmUrl: "",
    };
  }

  let model = emptyModel();
  let frozen = null;  // the model as it was when paused
  let connected = false;
  let following = false;
  let userMoved = false;  // after a pan or zoom the view stays where the user put it
  let serverClock = null;  // {utime, at}: the view's clock at a performance.now() instant
  let dirty = true;
  let drawn = { frames: 0, pixelsPerMetre: 0, messages: 0 };  // the last picture drawn

  let newestReceive = 0;  // the view's receive time of the newest message

  /// The view's clock now: its last statement, moved on by this page's clock, never before a message it sent.
  function nowUtime() {
    if (!serverClock) return newestReceive || null;
    return Math.max(newestReceive, serverClock.utime + (performance.now() - serverClock.at) * 1000);
  }

  function yawOf(q) {  // q = [w, x, y, z], body into world
    const [w, x, y, z] = q;
    return Math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z));
  }

  // ---- messages into the model -----------------------------------------------------------------------
  const handlers = {
    pose_t(message) {
      const pose = { x: message.position[0], y: message.position[1], yaw: yawOf(message.orientation),
                     utime: message.utime, speed: Math.hypot(message.velocity[0], message.velocity[1]) };
      if (!Number.isFinite(pose.x) || !Number.isFinite(pose.y)) return;
      model.pose = pose;
      if (!model.firstPose) model.firstPose = pose;
      model.poses += 1;
      const last = model.trajectory[model.trajectory.length - 1];
      if (!last || Math.hypot(pose.x - last[0], pose.y - last[1]) >= 0.05) model.trajectory.push([pose.x, pose.y]);
    },
    dv_graph_t(message) { model.graph = message; },
    path_t(message) { model.path = message; },
    goal_t(message) { model.goal = message; },
    exec_status_t(message) { model.exec = message; },
    planner_status_t(message) { model.planner = message; },
    affordance_t(message, line) { model.affordance = { message, receive_utime: line.receive_utime }; },
    force_t(message, line) {
      model.force = message;
      model.forceHistory.push([line.receive_utime, message.force_n]);
      const start = line.receive_utime - IfarView.ForceWindowS * 1e6;
      while (model.forceHistory.length && model.forceHistory[0][0] < start) model.forceHistory.shift();
    },
    world_state_t(message) { model.truth = message; },
    blocked_passage_t(message) {
      model.blockedPassages.push(message);
      if (model.blockedPassages.length > 20) model.blockedPassages.shift();
    },
    heartbeat_t(message, line) { model.heartbeats[message.process] = { message, receive_utime: line.receive_utime }; },
  };

  function onLine(line) {
    if (line.view) {
      if (line.view === "hello") {
        model = emptyModel();
        model.vehicle = Object.assign(model.vehicle, line.vehicle);
        model.lcmUrl = line.lcm_url;
      } else if (line.view === "trajectory") {
        model.trajectory = line.points;
        if (line.first_utime) model.firstPose = { utime: line.first_utime };
      } else if (line.view === "reset") {
        // A new timeline (a replay started again): keep only the vehicle's size and the heartbeats.
        const kept = { vehicle: model.vehicle, heartbeats: model.heartbeats, channels: model.channels,
                       lcmUrl: model.lcmUrl, messages: model.messages };
        model = Object.assign(emptyModel(), kept);
      } else if (line.view === "channels") {
        model.channels = line.channels;
        serverClock = { utime: line.now_utime, at: performance.now() };
      }
      dirty = true;
      return;
    }
    model.messages += 1;
    newestReceive = Math.max(newestReceive, line.receive_utime);
    const handler = handlers[line.type];
    if (handler) {
      handler(line.message, line);
      dirty = true;
    }
  }

  // ---- the connection: reconnects by itself --------------------------------------------------------------
  function connect() {
    const socket = new WebSocket(`${location.protocol === "https:" ? "wss" : "ws"}://${location.host}/ws`);
    socket.onopen = () => { connected = true; showConnection(); };
    socket.onmessage = (event) => {
      try { onLine(JSON.parse(event.data)); } catch (error) { console.warn("ifar view: bad line", error); }
    };
    socket.onclose = () => {
      connected = false;
      showConnection();
      setTimeout(connect, 1000);
    };
  }

  function showConnection() {
    const element = document.getElementById("connection");
    element.textContent = connected ? `live · ${model.lcmUrl || "LCM"}` : "disconnected, retrying";
    element.className = "connection " + (connected ? "up" : "down");
  }

  // ---- drawing -------------------------------------------------------------------------------------------
  function shown() { return frozen || model; }

  const pageErrors = [];  // what went wrong while drawing, for summary(): a test fails on any
  window.addEventListener("error", (event) => pageErrors.push(String(event.message)));

  // The next picture on the browser's animation frame, or after 100 ms where none comes (a hidden window
  // draws no animation frames, yet its panels and screenshots must stay current).
  let frameRequest = null, frameTimer = null;
  function scheduleFrame() {
    frameRequest = requestAnimationFrame(frame);
    frameTimer = setTimeout(frame, 100);
  }

  function frame() {
    cancelAnimationFrame(frameRequest);
    clearTimeout(frameTimer);
    try {
      drawFrame();
    } catch (error) {
      if (pageErrors.length < 20) pageErrors.push(String(error && error.stack || error));
      dirty = false;
    }
    scheduleFrame();
  }

  function drawFrame() {
    const current = shown();
    if (following && current.pose) { scene.centre = { x: current.pose.x, y: current.pose.y }; }
    if (!userMoved && !following && dirty) scene.fit(IfarView.boundsOf(current));
    if (dirty) {
      scene.draw(current, layers);
      const bar = scene.scaleBar(120);
      document.getElementById("scale-bar-line").style.width = `${bar.pixels}px`;
      document.getElementById("scale-bar-text").textContent = bar.text;
      drawn = { frames: drawn.frames + 1, pixelsPerMetre: scene.pixelsPerMetre, messages: current.messages };
      panels.update(current, nowUtime());
      showClock(current);
      showConnection();
      dirty = false;
    }
  }

  function showClock(current) {
    const element = document.getElementById("clock");
    if (!current.pose) { element.textContent = "no pose yet"; return; }
    const time = new Date(current.pose.utime / 1000).toISOString().replace("T", " ").slice(0, 23);
    const since = current.firstPose ? ((current.pose.utime - current.firstPose.utime) / 1e6).toFixed(1) : "0.0";
    const heading = (current.pose.yaw * 180 / Math.PI).toFixed(0);
    element.textContent = `${time} UTC · t ${since} s · ${current.pose.x.toFixed(2)}, ${current.pose.y.toFixed(2)} m, ` +
                          `${heading}° · ${(current.pose.speed || 0).toFixed(2)} m/s`;
  }

  // The panels age heartbeats by the clock even when no message comes.
  setInterval(() => { dirty = true; }, 500);

  // ---- controls -------------------------------------------------------------------------------------------
  function setPaused(paused) {
    frozen = paused ? structuredClone(model) : null;
    document.getElementById("paused-badge").hidden = !paused;
    const button = document.getElementById("pause");
    button.textContent = paused ? "Resume" : "Pause";
    button.classList.toggle("active", paused);
    dirty = true;
  }

  function setFollowing(follow) {
    following = follow;
    document.getElementById("follow").classList.toggle("active", follow);
    dirty = true;
  }

  function fitAll() {
    userMoved = false;
    setFollowing(false);
    scene.fit(IfarView.boundsOf(shown()));
    dirty = true;
  }

  const layerBox = document.getElementById("layers");
  for (const [name, title] of IfarView.Layers) {
    const label = document.createElement("label");
    label.innerHTML = `<input type="checkbox" data-layer="${name}"${layers[name] ? " checked" : ""}> ${title}`;
    label.firstChild.addEventListener("change", (event) => { layers[name] = event.target.checked; dirty = true; });
    layerBox.appendChild(label);
  }

  const legend = document.getElementById("legend");
  const C = IfarView.Colours;
  legend.innerHTML = [["global path", C.path], ["trajectory", C.trajectory], ["vehicle (POSE)", C.vehicleEdge],
                      ["interaction edge, push plan", C.interaction], ["visibility edge", "rgba(100, 170, 255, 0.6)"],
                      ["movable polygon", C.movableEdge], ["background polygon", C.backgroundEdge], ["goal", C.goal]]
    .map(([name, colour]) => `<div><span class="swatch" style="background:${colour}"></span>${name}</div>`).join("");

  document.getElementById("pause").onclick = () => setPaused(!frozen);
  document.getElementById("follow").onclick = () => { userMoved = true; setFollowing(!following); };
  document.getElementById("fit").onclick = fitAll;
  document.getElementById("clear-trajectory").onclick = () => { model.trajectory = []; dirty = true; };
  window.addEventListener("keydown", (event) => {
    if (event.target.tagName === "INPUT") return;
    if (event.key === " ") { setPaused(!frozen); event.preventDefault(); }
    else if (event.key === "f") { userMoved = true; setFollowing(!following); }
    else if (event.key === "0") fitAll();
  });

  const canvas = scene.canvas;
  let drag = null;
  canvas.addEventListener("pointerdown", (event) => {
    drag = { x: event.clientX, y: event.clientY };
    canvas.setPointerCapture(event.pointerId);
    canvas.classList.add("dragging");
  });
  canvas.addEventListener("pointermove", (event) => {
    const rect = canvas.getBoundingClientRect();
    const world = scene.toWorld(event.clientX - rect.left, event.clientY - rect.top);
    document.getElementById("cursor").textContent = `x ${world.x.toFixed(2)}  y ${world.y.toFixed(2)} m`;
    if (!drag) return;
    scene.panBy(event.clientX - drag.x, event.clientY - drag.y);
    drag = { x: event.clientX, y: event.clientY };
    userMoved = true;
    setFollowing(false);
  });
  canvas.addEventListener("pointerup", () => { drag = null; canvas.classList.remove("dragging"); });
  canvas.addEventListener("wheel", (event) => {
    event.preventDefault();
    const rect = canvas.getBoundingClientRect();
    scene.zoomAt(event.clientX - rect.left, event.clientY - rect.top, Math.exp(-event.deltaY * 0.0015));
    userMoved = true;
    dirty = true;
  }, { passive: false });
  window.addEventListener("resize", () => { scene.resize(); dirty = true; });

  // ---- what a test or the console can ask ------------------------------------------------------------------
  window.ifarView = {
    summary() {
      const current = shown(), now = nowUtime();
      return {
        connected, paused: frozen !== null, messages: current.messages,
        pose: current.pose, firstPose: current.firstPose, poses: current.poses,
        trajectoryPoints: current.trajectory.length,
        graph: current.graph && { utime: current.graph.utime, sequence: current.graph.sequence,
                                  polygons: current.graph.polygons.length, vertices: current.graph.vertices.length,
                                  edges: current.graph.edges.length,
                                  interactionEdges: current.graph.edges.filter((edge) => edge.kind === 1).length },
        pathWaypoints: current.path ? current.path.waypoints.length : 0,
        mode: current.exec ? IfarView.ExecutiveModes[current.exec.mode] : null,
        force: current.force ? current.force.force_n : null,
        pushPlans: current.path ? current.path.push_plans.length : 0,
        health: Object.keys(current.heartbeats).sort().map((process) => ({
          process, health: IfarView.HealthNames[current.heartbeats[process].message.health],
          utime: current.heartbeats[process].message.utime,
          ageS: now ? (now - current.heartbeats[process].receive_utime) / 1e6 : null })),
        scaleBar: document.getElementById("scale-bar-text").textContent,
        drawn,
        errors: pageErrors.slice(),
        pixelsPerMetre: scene.pixelsPerMetre,
        centre: Object.assign({}, scene.centre),
        following,
      };
    },
    pause() { setPaused(true); },
    resume() { setPaused(false); },
    setLayer(name, shownLayer) {
      layers[name] = shownLayer;
      const box = document.querySelector(`input[data-layer="${name}"]`);
      if (box) box.checked = shownLayer;
      dirty = true;
    },
    zoom(factor) { scene.zoomAt(scene.width / 2, scene.height / 2, factor); userMoved = true; dirty = true; },
    fit: fitAll,
  };

  connect();
  scheduleFrame();
})();
