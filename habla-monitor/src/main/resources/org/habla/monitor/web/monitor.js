// The HABLA monitor page: draws what the daemon's monitor sends on /live. It only reads; the one thing it
// writes is which method it looks at. Plots are uPlot charts.
"use strict";

const PLOT_WINDOW_S = 30;        // seconds of history a plot shows
const PLOT_MAX_POINTS = 1200;    // and at most this many points
const SVG_NS = "http://www.w3.org/2000/svg";

const state = {
  socket: null,
  selected: null,
  status: null,
  plots: {},        // producer -> {uplot, data, series}
  detail: null,     // the last detail message
  statusCount: 0,
  detailCount: 0,
};
window.hablaMonitor = state;

function el(tag, attrs, text) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

function svgEl(tag, attrs, text) {
  const e = document.createElementNS(SVG_NS, tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

function ms(us) { return us === undefined ? "" : (us / 1000).toFixed(us < 10000 ? 2 : 1); }

function ago(micros, nowMicros) {
  const s = Math.max(0, (nowMicros - micros) / 1e6);
  if (s < 120) return s.toFixed(0) + " s ago";
  if (s < 7200) return (s / 60).toFixed(0) + " min ago";
  return (s / 3600).toFixed(1) + " h ago";
}

// ---------------------------------------------------------------- the graph

async function loadGraph() {
  const text = await (await fetch("graph.svg")).text();
  const doc = new DOMParser().parseFromString(text, "image/svg+xml");
  const svg = document.importNode(doc.documentElement, true);
  document.getElementById("graph").replaceChildren(svg);
  for (const g of svg.querySelectorAll('g.node[id^="method:"]')) {
    g.addEventListener("click", () => select(g.id.substring("method:".length)));
    g.appendChild(svgEl("title", {}, g.id.substring("method:".length)));
  }
}

function methodClass(m) {
  if (m.state === "FAILED") return "failed";
  if (m.stale) return "stale";
  if (!m.ready || m.state !== "RUNNING") return "notready";
  return "running";
}

function paintGraph(st) {
  const svg = document.querySelector("#graph svg");
  if (!svg) return;
  for (const m of st.methods || []) {
    const g = svg.querySelector(`g.node[id="method:${CSS.escape(m.id)}"]`);
    if (!g) continue;
    g.classList.remove("running", "stale", "failed", "notready");
    g.classList.add(methodClass(m));
    g.classList.toggle("selected", m.id === state.selected);
    const title = g.querySelector("title");
    const lat = m.latency || {};
    title.textContent = `${m.id} (${m.type}): ${m.state}${m.stale ? ", stale" : ""}${m.ready ? "" : ", not ready"}` +
      `\n${(m.handledPerS || 0).toFixed(1)} handled/s, p50 ${ms(lat.p50Us)} ms, p99 ${ms(lat.p99Us)} ms` +
      (m.thread ? `\n${m.thread.inline ? "runs on " + m.thread.name + " (shared)" : "own thread"}: ${m.thread.reason}` : "") +
      (m.failure ? `\nfailed: ${m.failure}` : "") + (m.staleBecause ? `\nstale: ${m.staleBecause.why}` : "");
  }
  for (const i of st.interfaces || []) {
    const unavailable = i.unavailable || {};
    for (const g of svg.querySelectorAll(`g.node[id^="@${CSS.escape(i.id)}."]`)) {
      // A channel is down with its link, or alone while the device behind it is unavailable.
      const why = i.up ? unavailable[g.id.substring(i.id.length + 2)] : "link down";
      g.classList.toggle("link-up", why === undefined);
      g.classList.toggle("link-down", why !== undefined);
      let title = g.querySelector("title");
      if (!title) title = g.appendChild(svgEl("title", {}));
      title.textContent = g.id + (why === undefined ? "" : ": " + why);
    }
  }
}

// One row per device a driver reports, under its interface's row.
function deviceRows(i, nowMicros) {
  return Object.entries(i.devices || {}).map(([name, d]) => {
    const tr = el("tr", {id: "device-" + i.id + "-" + name, class: "device " + (d.online ? "up" : "down")});
    tr.appendChild(el("td", {}, "\u21b3 " + name));
    tr.appendChild(el("td", {class: d.online ? "up" : "down"}, d.online ? "online" : "OFFLINE"));
    tr.appendChild(el("td", {}, d.sinceMicros ? new Date(d.sinceMicros / 1000).toLocaleTimeString() + ", " +
      ago(d.sinceMicros, nowMicros) : ""));
    tr.appendChild(el("td", {}, d.detail || ""));
    return tr;
  });
}

// ---------------------------------------------------------------- status tables

function renderStatus(msg) {
  const st = msg.status;
  state.status = st;
  state.statusCount++;
  document.getElementById("system").textContent = "— " + st.system;
  document.getElementById("uptime").textContent = "up " + st.uptimeS.toFixed(0) + " s";
  const w = st.watchdog || {};
  const wd = document.getElementById("watchdog");
  wd.textContent = `watchdog ${w.tripped ? "TRIPPED" : "armed"} (${w.timeoutMs} ms, ${w.trips} trips)` +
    (w.lastReason ? `: ${w.lastReason}` : "");
  wd.className = "badge " + (w.tripped ? "tripped" : "up");

  const links = document.querySelector("#links tbody");
  links.replaceChildren(...(st.interfaces || []).flatMap(i => {
    const tr = el("tr", {id: "link-" + i.id, class: i.up ? "up" : "down"});
    tr.appendChild(el("td", {}, i.id + " (" + i.driver + ")"));
    tr.appendChild(el("td", {class: i.up ? "up" : "down"}, i.up ? "up" : "DOWN"));
    tr.appendChild(el("td", {}, i.sinceMicros ? new Date(i.sinceMicros / 1000).toLocaleTimeString() + ", " +
      ago(i.sinceMicros, msg.atMicros) : ""));
    const errs = (i.connections || []).filter(c => !c.up).map(c => c.name + (c.lastError ? ": " + c.lastError : ""));
    if (i.lastDrop) errs.push("last command dropped, on " + i.lastDrop.channel + ": " + i.lastDrop.why);
    tr.appendChild(el("td", {}, errs.join("; ")));
    return [tr, ...deviceRows(i, msg.atMicros)];
  }));

  const sockets = document.querySelector("#sockets tbody");
  sockets.replaceChildren(...(st.sockets || []).map(s => {
    const tr = el("tr", {});
    tr.appendChild(el("td", {}, s.socket));
    tr.appendChild(el("td", {class: "num"}, s.port));
    tr.appendChild(el("td", {class: "num"}, s.clients));
    const holder = s.holder || s.controlHolder || s.heldBy || (s.control && (s.control.holder || s.control.heldBy));
    tr.appendChild(el("td", {}, holder === undefined ? "" : (typeof holder === "string" ? holder : JSON.stringify(holder))));
    tr.appendChild(el("td", {class: "num"}, s.dropped));
    return tr;
  }));

  const methods = document.querySelector("#methods tbody");
  methods.replaceChildren(...(st.methods || []).map(m => {
    const tr = el("tr", {id: "row-" + m.id});
    tr.addEventListener("click", () => select(m.id));
    const lat = m.latency || {};
    let dropped = 0;
    for (const i of Object.values(m.inputs || {})) dropped += i.dropped || 0;
    const cls = methodClass(m);
    tr.appendChild(el("td", {}, m.id));
    tr.appendChild(el("td", {}, m.type));
    tr.appendChild(el("td", {}, m.layer));
    const stateCell = el("td", {class: cls === "running" ? "up" : cls === "failed" ? "down" : cls},
      m.state.toLowerCase() + (m.stale ? ", stale" + (m.staleBecause ? " (" + m.staleBecause.source + ")" : "") : "") +
      (m.ready ? "" : ", not ready"));
    if (m.staleBecause) stateCell.title = m.staleBecause.why;
    tr.appendChild(stateCell);
    tr.appendChild(el("td", {class: "num"}, (m.handledPerS || 0).toFixed(1)));
    tr.appendChild(el("td", {class: "num"}, ms(lat.p50Us)));
    tr.appendChild(el("td", {class: "num"}, ms(lat.p99Us)));
    tr.appendChild(el("td", {class: "num"}, dropped));
    tr.appendChild(el("td", {}, Object.entries(m.outputs || {}).map(([k, v]) => k + " " + v).join(", ")));
    return tr;
  }));
  paintGraph(st);
}

// ---------------------------------------------------------------- one method's details

function select(id) {
  state.selected = id;
  state.detail = null;
  for (const p of Object.values(state.plots)) p.uplot.destroy();
  state.plots = {};
  document.getElementById("detail-outputs").replaceChildren();
  document.getElementById("detail-camera").hidden = true;
  document.getElementById("detail").hidden = false;
  document.getElementById("detail-name").textContent = id;
  if (state.socket && state.socket.readyState === WebSocket.OPEN) {
    state.socket.send(JSON.stringify({select: id}));
  }
  if (state.status) paintGraph(state.status);
}

function outputCard(producer, kind) {
  const id = "out-" + producer.replace(/[^A-Za-z0-9_-]/g, "_");
  let card = document.getElementById(id);
  if (!card) {
    card = el("div", {id, class: "output", "data-producer": producer});
    card.appendChild(el("h3", {}, producer + " (" + kind + ")"));
    card.appendChild(el("pre", {class: "last"}, "no value yet"));
    document.getElementById("detail-outputs").appendChild(card);
  }
  return card;
}

function plot(card, producer, series, points) {
  let p = state.plots[producer];
  if (p && p.series.join() !== series.join()) {
    p.uplot.destroy();
    card.querySelector(".plot").remove();
    p = null;
  }
  if (!p) {
    const div = el("div", {class: "plot"});
    card.appendChild(div);
    const colours = ["#1f5fbf", "#c0392b", "#27ae60", "#8e44ad", "#d35400", "#16a085", "#2c3e50", "#f39c12"];
    const opts = {
      width: 420, height: 180,
      series: [{}].concat(series.map((s, i) => ({label: s, stroke: colours[i % colours.length], width: 1.5}))),
      scales: {x: {time: true}},
      legend: {show: true},
    };
    const data = [[]].concat(series.map(() => []));
    p = {uplot: new uPlot(opts, data, div), data, series};
    state.plots[producer] = p;
  }
  for (const pt of points) {
    for (let i = 0; i < p.data.length; i++) p.data[i].push(i < pt.length ? pt[i] : null);
  }
  const last = p.data[0][p.data[0].length - 1];
  let cut = 0;
  while (cut < p.data[0].length && (p.data[0][cut] < last - PLOT_WINDOW_S || p.data[0].length - cut > PLOT_MAX_POINTS)) cut++;
  if (cut > 0) for (const a of p.data) a.splice(0, cut);
  p.uplot.setData(p.data);
}

function renderDetail(msg) {
  if (msg.method !== state.selected) return;
  state.detail = msg;
  state.detailCount++;
  for (const [producer, o] of Object.entries(msg.outputs)) {
    const card = outputCard(producer, o.kind);
    if (o.last !== undefined) {
      card.querySelector(".last").textContent = (o.stale ? "[stale] " : "") + "#" + o.count + "  " +
        (typeof o.last === "string" ? o.last : JSON.stringify(o.last, null, 1));
    }
    if (o.points && o.series && o.series.length) plot(card, producer, o.series, o.points);
    if (o.texts) {
      let list = card.querySelector("ol");
      if (!list) { list = el("ol", {reversed: ""}); card.appendChild(list); }
      for (const t of o.texts) {
        const measure = t.confidence !== undefined ? ` (confidence ${t.confidence.toFixed(2)})`
          : t.score !== undefined ? ` (score ${t.score.toPrecision(3)})` : "";
        list.insertBefore(el("li", {class: "text"}, t.text + measure), list.firstChild);
      }
      while (list.children.length > 10) list.lastChild.remove();
    }
    if (o.levelDb !== undefined) {
      let meter = card.querySelector("meter");
      if (!meter) {
        card.appendChild(el("span", {}, "level "));
        meter = el("meter", {min: "-90", max: "0", low: "-40", high: "-6", optimum: "-20"});
        card.appendChild(meter);
        card.appendChild(el("span", {class: "level"}));
      }
      meter.value = o.levelDb;
      card.querySelector(".level").textContent = " " + o.levelDb.toFixed(1) + " dBFS";
    }
    if (o.blobs) drawBlobs(o.blobs);
  }
  if (msg.image) {
    const cam = document.getElementById("detail-camera");
    cam.hidden = false;
    if (msg.image.src) {
      document.getElementById("camera-frame").src = msg.image.src;
      document.getElementById("camera-caption").textContent =
        `${msg.image.producer}, ${msg.image.width}×${msg.image.height}`;
      document.getElementById("camera-blobs").setAttribute("viewBox", `0 0 ${msg.image.width} ${msg.image.height}`);
    } else {
      document.getElementById("camera-caption").textContent = msg.image.error;
    }
  }
}

function drawBlobs(rec) {
  const svg = document.getElementById("camera-blobs");
  if (rec.width && rec.height) svg.setAttribute("viewBox", `0 0 ${rec.width} ${rec.height}`);
  svg.replaceChildren(...(rec.blobs || []).flatMap(b => [
    svgEl("rect", {x: b.x, y: b.y, width: b.w, height: b.h, "vector-effect": "non-scaling-stroke", class: "blob"}),
    svgEl("text", {x: b.x, y: Math.max(9, b.y - 2)}, `${b.label} ${b.area}`),
  ]));
}

// ---------------------------------------------------------------- the connection

function connect() {
  const badge = document.getElementById("connection");
  const ws = new WebSocket(`ws://${location.host}/live`);
  state.socket = ws;
  ws.onopen = () => {
    badge.textContent = "live";
    badge.className = "badge up";
    if (state.selected) ws.send(JSON.stringify({select: state.selected}));
  };
  ws.onmessage = e => {
    const msg = JSON.parse(e.data);
    if (msg.type === "status") renderStatus(msg);
    else if (msg.type === "detail") renderDetail(msg);
  };
  ws.onclose = () => {
    badge.textContent = "daemon not reachable — retrying";
    badge.className = "badge down";
    setTimeout(connect, 1000);
  };
}

loadGraph().then(connect);
