// The map: world metres (x right, y up) onto the canvas, to scale, with pan and zoom. Draws what the model
// holds: the planner's polygons and DV-graph, the global path and its push plans, the vehicle's footprint
// and trajectory, the goal, the executive's target, blocked passages and the simulator's ground truth.
"use strict";

window.IfarView = window.IfarView || {};

IfarView.Layers = [
  ["background", "background polygons", true],
  ["movable", "movable polygons", true],
  ["visibility", "visibility edges", true],
  ["interaction", "interaction edges", true],
  ["vertices", "graph vertices", true],
  ["path", "global path", true],
  ["pushPlans", "push plans", true],
  ["trajectory", "trajectory", true],
  ["vehicle", "vehicle footprint", true],
  ["goal", "goal and target", true],
  ["truth", "ground truth (sim)", true],
  ["grid", "grid", true],
];

IfarView.Colours = {
  background: "#15181d",
  gridMinor: "#1f232a",
  gridMajor: "#2b313b",
  axis: "#3d4654",
  backgroundFill: "rgba(120, 130, 150, 0.55)",
  backgroundEdge: "#9aa4b8",
  movableFill: "rgba(255, 152, 0, 0.35)",
  movableEdge: "#ffa726",
  visibility: "rgba(100, 170, 255, 0.16)",
  interaction: "#e040fb",
  corner: "#b0bfd6",
  topological: "#ffd54f",
  path: "#66bb6a",
  pushPlan: "#e040fb",
  objectPlan: "#ffb74d",
  trajectory: "#29b6f6",
  vehicleFill: "rgba(0, 229, 255, 0.25)",
  vehicleEdge: "#00e5ff",
  goal: "#ff5252",
  target: "#ffee58",
  truth: "rgba(255, 255, 255, 0.75)",
  blocked: "#ff1744",
};

IfarView.Scene = class {
  constructor(canvas) {
    this.canvas = canvas;
    this.context = canvas.getContext("2d");
    this.centre = { x: 16, y: 16 };  // world point at the canvas centre, metres
    this.pixelsPerMetre = 20;
    this.resize();
  }

  resize() {
    const ratio = window.devicePixelRatio || 1;
    const rect = this.canvas.getBoundingClientRect();
    this.width = Math.max(1, rect.width);
    this.height = Math.max(1, rect.height);
    this.canvas.width = Math.round(this.width * ratio);
    this.canvas.height = Math.round(this.height * ratio);
    this.context.setTransform(ratio, 0, 0, ratio, 0, 0);
  }

  toScreen(x, y) {
    return [this.width / 2 + (x - this.centre.x) * this.pixelsPerMetre,
            this.height / 2 - (y - this.centre.y) * this.pixelsPerMetre];
  }

  toWorld(px, py) {
    return { x: this.centre.x + (px - this.width / 2) / this.pixelsPerMetre,
             y: this.centre.y - (py - this.height / 2) / this.pixelsPerMetre };
  }

  panBy(dx, dy) {
    this.centre.x -= dx / this.pixelsPerMetre;
    this.centre.y += dy / this.pixelsPerMetre;
  }

  /// Zooms by `factor` keeping the world point under (px, py) where it is.
  zoomAt(px, py, factor) {
    const before = this.toWorld(px, py);
    this.pixelsPerMetre = Math.min(2000, Math.max(0.5, this.pixelsPerMetre * factor));
    const after = this.toWorld(px, py);
    this.centre.x += before.x - after.x;
    this.centre.y += before.y - after.y;
  }

  /// Shows the rectangle [x0, x1] x [y0, y1] with a margin.
  fit(bounds) {
    if (!bounds) return;
    const spanX = Math.max(2, bounds.x1 - bounds.x0), spanY = Math.max(2, bounds.y1 - bounds.y0);
    this.centre = { x: (bounds.x0 + bounds.x1) / 2, y: (bounds.y0 + bounds.y1) / 2 };
    this.pixelsPerMetre = Math.max(0.5, 0.9 * Math.min(this.width / spanX, this.height / spanY));
  }

  /// A length for the scale bar near `targetPixels` long: 1, 2 or 5 times a power of ten metres.
  scaleBar(targetPixels) {
    const metres = targetPixels / this.pixelsPerMetre;
    const power = Math.pow(10, Math.floor(Math.log10(metres)));
    let nice = power;
    for (const step of [1, 2, 5, 10]) if (step * power <= metres) nice = step * power;
    const text = nice >= 1 ? `${nice} m` : `${Math.round(nice * 100)} cm`;
    return { pixels: nice * this.pixelsPerMetre, text };
  }

  draw(model, layers) {
    const g = this.context, C = IfarView.Colours;
    g.fillStyle = C.background;
    g.fillRect(0, 0, this.width, this.height);
    if (layers.grid) this.drawGrid();
    const graph = model.graph;
    if (graph) {
      for (const polygon of graph.polygons) {
        const movable = polygon.kind === 1;
        if (movable ? !layers.movable : !layers.background) continue;
        this.polygon(polygon.x, polygon.y, movable ? C.movableFill : C.backgroundFill,
                     movable ? C.movableEdge : C.backgroundEdge, 1.2);
      }
      this.drawGraph(graph, layers);
    }
    if (layers.truth && model.truth) this.drawTruth(model);
    if (layers.trajectory && model.trajectory.length > 1) {
      this.polyline(model.trajectory, C.trajectory, 2);
    }
    if (model.path && model.path.valid) {
      if (layers.path) this.drawPath(model.path);
      if (layers.pushPlans) for (const plan of model.path.push_plans) this.drawPushPlan(plan);
    }
    if (layers.goal) this.drawGoalAndTarget(model);
    for (const passage of model.blockedPassages) this.drawBlocked(passage);
    if (layers.vehicle && model.pose) this.drawVehicle(model.pose, model.vehicle, C.vehicleFill, C.vehicleEdge, []);
  }

  drawGrid() {
    const g = this.context, C = IfarView.Colours;
    const topLeft = this.toWorld(0, 0), bottomRight = this.toWorld(this.width, this.height);
    // Minor lines 1 m apart, major every 5 m; coarser when lines would crowd.
    let minor = 1;
    while (minor * this.pixelsPerMetre < 8) minor *= 5;
    const major = minor * 5;
    for (const [step, colour] of [[minor, C.gridMinor], [major, C.gridMajor]]) {
      g.strokeStyle = colour;
      g.lineWidth = 1;
      g.beginPath();
      for (let x = Math.floor(topLeft.x / step) * step; x <= bottomRight.x; x += step) {
        const [px] = this.toScreen(x, 0);
        g.moveTo(Math.round(px) + 0.5, 0);
        g.lineTo(Math.round(px) + 0.5, this.height);
      }
      for (let y = Math.floor(bottomRight.y / step) * step; y <= topLeft.y; y += step) {
        const [, py] = this.toScreen(0, y);
        g.moveTo(0, Math.round(py) + 0.5);
        g.lineTo(this.width, Math.round(py) + 0.5);
      }
      g.stroke();
    }
    const [ox, oy] = this.toScreen(0, 0);
    g.strokeStyle = C.axis;
    g.beginPath();
    g.moveTo(ox, 0); g.lineTo(ox, this.height);
    g.moveTo(0, oy); g.lineTo(this.width, oy);
    g.stroke();
  }

  drawGraph(graph, layers) {
    const g = this.context, C = IfarView.Colours;
    const vertices = new Map();
    for (const vertex of graph.vertices) vertices.set(vertex.id, vertex);
    if (layers.visibility) {
      g.strokeStyle = C.visibility;
      g.lineWidth = 1;
      g.beginPath();
      for (const edge of graph.edges) {
        if (edge.kind !== 0) continue;
        const from = vertices.get(edge.from_id), to = vertices.get(edge.to_id);
        if (!from || !to) continue;
        g.moveTo(...this.toScreen(from.x, from.y));
        g.lineTo(...this.toScreen(to.x, to.y));
      }
      g.stroke();
    }
    if (layers.interaction) {
      g.strokeStyle = C.interaction;
      g.fillStyle = C.interaction;
      g.lineWidth = 1.5;
      g.setLineDash([6, 4]);
      for (const edge of graph.edges) {
        if (edge.kind !== 1) continue;
        const from = vertices.get(edge.from_id), to = vertices.get(edge.to_id);
        if (!from || !to) continue;
        const [x0, y0] = this.toScreen(from.x, from.y), [x1, y1] = this.toScreen(to.x, to.y);
        g.beginPath(); g.moveTo(x0, y0); g.lineTo(x1, y1); g.stroke();
        this.arrowHead(x0, y0, x1, y1, 8);
      }
      g.setLineDash([]);
    }
    if (layers.vertices) {
      for (const vertex of graph.vertices) {
        const [px, py] = this.toScreen(vertex.x, vertex.y);
        if (vertex.kind === 1) {
          g.fillStyle = C.topological;
          g.beginPath();
          g.moveTo(px, py - 5); g.lineTo(px + 5, py); g.lineTo(px, py + 5); g.lineTo(px - 5, py);
          g.closePath(); g.fill();
        } else if (vertex.kind === 0) {
          g.fillStyle = C.corner;
          g.fillRect(px - 1.5, py - 1.5, 3, 3);
        }
      }
    }
  }

  drawPath(path) {
    const g = this.context, C = IfarView.Colours;
    const points = path.waypoints.map((waypoint) => [waypoint.x, waypoint.y]);
    this.polyline(points, C.path, 3);
    for (const waypoint of path.waypoints) {
      const [px, py] = this.toScreen(waypoint.x, waypoint.y);
      g.fillStyle = waypoint.kind === 0 ? C.path : waypoint.kind === 1 ? C.topological : C.pushPlan;
      g.beginPath(); g.arc(px, py, waypoint.kind === 0 ? 3 : 5, 0, 2 * Math.PI); g.fill();
    }
  }

  drawPushPlan(plan) {
    const g = this.context, C = IfarView.Colours;
    const vehicleTrack = [[plan.contact_x, plan.contact_y]];
    const objectTrack = [];
    for (const control of plan.controls) {
      vehicleTrack.push([control.vehicle_x, control.vehicle_y]);
      objectTrack.push([control.object_x, control.object_y]);
    }
    g.setLineDash([5, 4]);
    this.polyline(vehicleTrack, C.pushPlan, 2);
    g.setLineDash([2, 3]);
    this.polyline(objectTrack, C.objectPlan, 2);
    g.setLineDash([]);
    // The contact pose: where and which way the vehicle meets the object.
    const [px, py] = this.toScreen(plan.contact_x, plan.contact_y);
    const length = Math.max(12, 0.6 * this.pixelsPerMetre);
    const tx = px + length * Math.cos(plan.contact_heading), ty = py - length * Math.sin(plan.contact_heading);
    g.strokeStyle = C.pushPlan; g.fillStyle = C.pushPlan; g.lineWidth = 2;
    g.beginPath(); g.moveTo(px, py); g.lineTo(tx, ty); g.stroke();
    this.arrowHead(px, py, tx, ty, 8);
    if (objectTrack.length > 0) {
      const [ex, ey] = this.toScreen(...objectTrack[objectTrack.length - 1]);
      g.strokeStyle = C.objectPlan; g.lineWidth = 2;
      g.beginPath(); g.arc(ex, ey, 5, 0, 2 * Math.PI); g.stroke();
    }
    this.label(`push ${plan.object_id}: J ${plan.expected_cost.toFixed(1)}`, px + 8, py + 14, C.pushPlan);
  }

  drawGoalAndTarget(model) {
    const g = this.context, C = IfarView.Colours;
    // The goal as sent; on a replay (which never publishes GOAL) the end of the path the planner works to.
    let goal = model.goal && !model.goal.cancel ? model.goal : null;
    if (!goal && model.path && model.path.valid && model.path.waypoints.length > 0) {
      const last = model.path.waypoints[model.path.waypoints.length - 1];
      goal = { x: last.x, y: last.y, goal_id: model.path.goal_id };
    }
    if (goal) {
      const [px, py] = this.toScreen(goal.x, goal.y);
      g.strokeStyle = C.goal; g.lineWidth = 2.5;
      g.beginPath(); g.arc(px, py, 9, 0, 2 * Math.PI); g.stroke();
      g.beginPath(); g.moveTo(px - 13, py); g.lineTo(px + 13, py); g.moveTo(px, py - 13); g.lineTo(px, py + 13); g.stroke();
      this.label(`goal ${goal.goal_id}`, px + 12, py - 10, C.goal);
    }
    // The executive's target while it drives: following, approaching, pushing or waiting for a replan.
    if (model.exec && model.exec.mode >= 1 && model.exec.mode <= 4) {
      const [px, py] = this.toScreen(model.exec.target_x, model.exec.target_y);
      g.strokeStyle = C.target; g.lineWidth = 1.5;
      g.beginPath(); g.arc(px, py, 5, 0, 2 * Math.PI); g.stroke();
    }
  }

  drawBlocked(passage) {
    const g = this.context, C = IfarView.Colours;
    const [x0, y0] = this.toScreen(passage.from_x, passage.from_y), [x1, y1] = this.toScreen(passage.to_x, passage.to_y);
    g.strokeStyle = C.blocked; g.lineWidth = 2;
    g.setLineDash([3, 3]);
    g.beginPath(); g.moveTo(x0, y0); g.lineTo(x1, y1); g.stroke();
    g.setLineDash([]);
    g.beginPath(); g.moveTo(x1 - 6, y1 - 6); g.lineTo(x1 + 6, y1 + 6); g.moveTo(x1 - 6, y1 + 6); g.lineTo(x1 + 6, y1 - 6); g.stroke();
  }

  drawTruth(model) {
    const C = IfarView.Colours, truth = model.truth, g = this.context;
    for (const object of truth.objects) {
      if (!object.movable) continue;
      const [px, py] = this.toScreen(object.x, object.y);
      g.strokeStyle = C.truth; g.lineWidth = 1;
      g.beginPath(); g.moveTo(px - 5, py); g.lineTo(px + 5, py); g.moveTo(px, py - 5); g.lineTo(px, py + 5); g.stroke();
      this.label(`#${object.id}`, px + 6, py - 6, C.truth);
    }
    g.setLineDash([4, 3]);
    this.drawVehicle({ x: truth.vehicle_x, y: truth.vehicle_y, yaw: truth.vehicle_heading }, model.vehicle, null, C.truth);
    g.setLineDash([]);
  }

  drawVehicle(pose, vehicle, fill, edge) {
    const g = this.context;
    const halfLength = vehicle.length_m / 2, halfWidth = vehicle.width_m / 2;
    const cos = Math.cos(pose.yaw), sin = Math.sin(pose.yaw);
    const corner = (ax, ay) => this.toScreen(pose.x + ax * cos - ay * sin, pose.y + ax * sin + ay * cos);
    const outline = [corner(halfLength, halfWidth), corner(-halfLength, halfWidth), corner(-halfLength, -halfWidth),
                     corner(halfLength, -halfWidth)];
    g.beginPath();
    g.moveTo(...outline[0]);
    for (const point of outline.slice(1)) g.lineTo(...point);
    g.closePath();
    if (fill) { g.fillStyle = fill; g.fill(); }
    g.strokeStyle = edge; g.lineWidth = 1.5; g.stroke();
    // The bumper: the front face, drawn heavier.
    const halfBumper = (vehicle.bumper_width_m || vehicle.width_m) / 2;
    g.lineWidth = 3.5;
    g.beginPath(); g.moveTo(...corner(halfLength, halfBumper)); g.lineTo(...corner(halfLength, -halfBumper)); g.stroke();
    // Heading.
    const [cx, cy] = this.toScreen(pose.x, pose.y), [hx, hy] = corner(halfLength + 0.35, 0);
    g.lineWidth = 1.5;
    g.beginPath(); g.moveTo(cx, cy); g.lineTo(hx, hy); g.stroke();
    if (fill) { g.fillStyle = edge; this.arrowHead(cx, cy, hx, hy, 6); }
  }

  polygon(xs, ys, fill, edge, width) {
    if (xs.length < 2) return;
    const g = this.context;
    g.beginPath();
    g.moveTo(...this.toScreen(xs[0], ys[0]));
    for (let index = 1; index < xs.length; ++index) g.lineTo(...this.toScreen(xs[index], ys[index]));
    g.closePath();
    g.fillStyle = fill; g.fill();
    g.strokeStyle = edge; g.lineWidth = width; g.stroke();
  }

  polyline(points, colour, width) {
    if (points.length < 2) return;
    const g = this.context;
    g.strokeStyle = colour; g.lineWidth = width; g.lineJoin = "round"; g.lineCap = "round";
    g.beginPath();
    g.moveTo(...this.toScreen(points[0][0], points[0][1]));
    for (let index = 1; index < points.length; ++index) g.lineTo(...this.toScreen(points[index][0], points[index][1]));
    g.stroke();
  }

  arrowHead(x0, y0, x1, y1, size) {
    const g = this.context, angle = Math.atan2(y1 - y0, x1 - x0);
    g.beginPath();
    g.moveTo(x1, y1);
    g.lineTo(x1 - size * Math.cos(angle - 0.4), y1 - size * Math.sin(angle - 0.4));
    g.lineTo(x1 - size * Math.cos(angle + 0.4), y1 - size * Math.sin(angle + 0.4));
    g.closePath(); g.fill();
  }

  label(text, px, py, colour) {
    const g = this.context;
    g.font = "11px 'DejaVu Sans Mono', monospace";
    g.fillStyle = "rgba(21, 24, 29, 0.7)";
    const width = g.measureText(text).width;
    g.fillRect(px - 2, py - 10, width + 4, 13);
    g.fillStyle = colour;
    g.fillText(text, px, py);
  }
};

/// The world rectangle holding the graph, the trajectory, the vehicle and the goal, or null.
IfarView.boundsOf = function (model) {
  let bounds = null;
  const add = (x, y) => {
    if (!Number.isFinite(x) || !Number.isFinite(y)) return;
    if (!bounds) bounds = { x0: x, x1: x, y0: y, y1: y };
    bounds.x0 = Math.min(bounds.x0, x); bounds.x1 = Math.max(bounds.x1, x);
    bounds.y0 = Math.min(bounds.y0, y); bounds.y1 = Math.max(bounds.y1, y);
  };
  if (model.graph) for (const polygon of model.graph.polygons) polygon.x.forEach((x, index) => add(x, polygon.y[index]));
  for (const [x, y] of model.trajectory) add(x, y);
  if (model.pose) { add(model.pose.x - 2, model.pose.y - 2); add(model.pose.x + 2, model.pose.y + 2); }
  if (model.goal) add(model.goal.x, model.goal.y);
  return bounds;
};
