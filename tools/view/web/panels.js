// The side panel: the executive's mode and reason, the planner's state and numbers, the force with a plot of
// the last seconds, the last affordance, every process's heartbeat and the channels' rates.
"use strict";

window.IfarView = window.IfarView || {};

IfarView.ExecutiveModes = ["idle", "follow", "approach", "push", "replan wait", "stop", "e-stop", "arrived"];
IfarView.PlannerStates = ["idle", "planning", "no path", "arrived", "bad input"];
IfarView.HealthNames = ["OK", "DEGRADED", "ERROR"];
IfarView.AffordanceReasons = ["did not move (unpushable)", "cost higher than planned", "cost lower than planned",
                              "jammed"];
// A process whose last beat is older than this is shown as silent (beats come once a second).
IfarView.SilentAfterS = 3;
// The force plot spans this many seconds.
IfarView.ForceWindowS = 10;

IfarView.Panels = class {
  constructor() {
    this.element = (id) => document.getElementById(id);
  }

  facts(id, rows) {
    this.element(id).innerHTML = rows
      .map(([name, value]) => `<tr><td>${escapeHtml(name)}</td><td>${escapeHtml(String(value))}</td></tr>`)
      .join("");
  }

  badge(id, text, level) {
    const badge = this.element(id);
    badge.textContent = text;
    badge.className = "badge " + level;
  }

  update(model, nowUtime) {
    this.updateExecutive(model.exec);
    this.updatePlanner(model.planner, model.path, model.graph);
    this.updateForce(model);
    this.updateAffordance(model.affordance, nowUtime);
    this.updateHealth(model.heartbeats, nowUtime);
    this.updateChannels(model.channels);
  }

  updateExecutive(exec) {
    if (!exec) return;
    const mode = IfarView.ExecutiveModes[exec.mode] || `mode ${exec.mode}`;
    const level = exec.mode === 7 ? "ok" : exec.mode >= 5 ? "error" : exec.mode === 4 ? "warn" : "info";
    this.badge("exec-mode", mode, level);
    this.element("exec-reason").textContent = exec.reason;
    const stale = ["pose", "path", "force", "motor", "obstacles"].filter((_, bit) => exec.stale & (1 << bit));
    this.facts("exec-facts", [
      ["goal", exec.goal_id < 0 ? "none" : exec.goal_id],
      ["target", `${exec.target_x.toFixed(2)}, ${exec.target_y.toFixed(2)} m`],
      ["waypoint", exec.waypoint_index],
      ["pushing object", exec.target_object_id < 0 ? "–" : exec.target_object_id],
      ["pushes / replans", `${exec.pushes} / ${exec.replans}`],
      ["stale inputs", stale.length ? stale.join(", ") : "none"],
    ]);
  }

  updatePlanner(status, path, graph) {
    if (status) {
      const state = IfarView.PlannerStates[status.state] || `state ${status.state}`;
      const level = status.state === 1 || status.state === 3 ? "ok" : status.state === 0 ? "info" : "error";
      this.badge("planner-state", state, level);
      this.element("planner-message").textContent = status.message;
    }
    const rows = [];
    if (status) {
      rows.push(["frames", status.frames]);
      rows.push(["graph vertices / edges", `${status.num_vertices} / ${status.num_edges}`]);
      rows.push(["interaction edges", status.num_interaction_edges]);
      rows.push(["frame time", `${status.total_ms.toFixed(1)} ms`]);
    }
    if (graph) rows.push(["DV_GRAPH", `${graph.polygons.length} polygons, ${graph.vertices.length} vertices`]);
    if (path) {
      rows.push(["path", path.valid ? `${path.length_m.toFixed(1)} m, cost ${path.cost.toFixed(1)}` : "none"]);
      rows.push(["push plans", path.push_plans.length]);
    }
    this.facts("planner-facts", rows);
  }

  updateForce(model) {
    const force = model.force;
    if (!force) return;
    const range = model.vehicle.force_range_n || 800;
    this.element("force-value").textContent = `${force.force_n.toFixed(0)} N`;
    this.element("force-gauge").style.width = `${Math.min(100, (100 * force.force_n) / range)}%`;
    const flags = ["overload", "fault", "silent", "counter stuck"].filter((_, bit) => force.status & (1 << bit));
    this.element("force-flags").textContent = flags.length ? "sensor: " + flags.join(", ") : "";
    this.plotForce(model.forceHistory);
  }

  plotForce(history) {
    const canvas = this.element("force-plot"), g = canvas.getContext("2d");
    const width = canvas.width, height = canvas.height;
    g.clearRect(0, 0, width, height);
    if (history.length < 2) return;
    const end = history[history.length - 1][0], start = end - IfarView.ForceWindowS * 1e6;
    const top = Math.max(50, ...history.map(([, f]) => f)) * 1.15;
    g.strokeStyle = "#2b313b";
    g.beginPath(); g.moveTo(0, height - 0.5); g.lineTo(width, height - 0.5); g.stroke();
    g.strokeStyle = "#ffb300"; g.lineWidth = 1.5;
    g.beginPath();
    history.forEach(([t, f], index) => {
      const x = ((t - start) / (end - start)) * width, y = height - (f / top) * (height - 4) - 1;
      if (index === 0) g.moveTo(x, y); else g.lineTo(x, y);
    });
    g.stroke();
    g.fillStyle = "#8a94a3"; g.font = "10px sans-serif";
    g.fillText(`${top.toFixed(0)} N`, 3, 10);
    g.fillText(`${IfarView.ForceWindowS} s`, width - 24, height - 4);
  }

  updateAffordance(affordance, nowUtime) {
    if (!affordance) return;
    const message = affordance.message;
    const age = nowUtime ? ((nowUtime - affordance.receive_utime) / 1e6).toFixed(0) + " s ago" : "";
    this.facts("affordance-facts", [
      ["object", `${message.object_id} ${age}`],
      ["pushable", message.pushable ? "yes" : "NO"],
      ["why", IfarView.AffordanceReasons[message.reason] || message.reason],
      ["push force", `${message.push_force_n.toFixed(0)} N`],
      ["affordance mu", message.affordance.toFixed(3)],
      ["cost planned / measured", `${message.planned_cost.toFixed(1)} / ${message.measured_cost.toFixed(1)}`],
    ]);
  }

  updateHealth(heartbeats, nowUtime) {
    const rows = Object.keys(heartbeats).sort().map((process) => {
      const beat = heartbeats[process];
      const ageS = nowUtime ? (nowUtime - beat.receive_utime) / 1e6 : 0;
      const silent = ageS > IfarView.SilentAfterS;
      const health = silent ? "SILENT" : IfarView.HealthNames[beat.message.health] || beat.message.health;
      const rowClass = "health-" + health.toLowerCase();
      const detail = silent ? `no beat for ${ageS.toFixed(0)} s` : beat.message.message;
      return `<tr class="${rowClass}" data-process="${escapeHtml(process)}"><td>${escapeHtml(process)}` +
             `<div class="message">${escapeHtml(detail)}</div></td><td class="health">${health}</td>` +
             `<td class="mono">${ageS.toFixed(1)} s</td></tr>`;
    });
    this.element("health-table").tBodies[0].innerHTML =
      rows.length ? rows.join("") : '<tr><td colspan="3">no heartbeat yet</td></tr>';
  }

  updateChannels(channels) {
    if (!channels) return;
    this.element("channel-table").tBodies[0].innerHTML = channels
      .map((channel) => `<tr><td>${escapeHtml(channel.channel)}</td><td>${escapeHtml(channel.type || "?")}</td>` +
                        `<td class="mono">${channel.rate_hz.toFixed(1)}</td></tr>`)
      .join("");
  }
};

function escapeHtml(text) {
  return text.replace(/[&<>"']/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;" })[c]);
}
