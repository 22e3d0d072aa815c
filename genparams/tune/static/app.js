// The tuning page: node list, a node's form, edits applied through its parameter services.
import { api } from "./api.js";
import { InputError, diffTable, el, mapGroup, row, section } from "./form.js";
import { keepControls } from "./keep.js";
import { parseJson, shownJson, stringifyJson } from "./json.js";

// pending: edits not applied yet; drafts: values being typed (checked, not applied);
// applying: the edits of the apply in flight and the names the node changed meanwhile.
// loading: the node whose read for a new form is in flight; missed: one of its events came
// meanwhile; reads: reads started (only the newest counts); fresher: the names events set
// during a catch-up read. unconfirmed: sets the node is still working on (the server's 202),
// by the id its "set" event will carry, each with the node and the edits it sent.
const page = { readOnly: false, node: null, view: null, pending: new Map(), drafts: new Map(),
  applying: null, reload: null, checkTimer: null, checks: 0, loading: null, missed: false,
  reads: 0, fresher: null, unconfirmed: new Map() };
const CHECK_DELAY_MS = 150;

function status(text) { document.getElementById("status").textContent = text; }
const liveMode = () => document.getElementById("live").checked;

// An entry's parameter: the place's path, the key, the field ("" for a per-item entry).
const entryName = (place, key, field) => [place.path, key, field].filter(Boolean).join(".");

// What the page knows of each parameter: the schema's words, else the node's descriptor.
// Mapped entries come from the places the server found (places.py): where each group
// stands on the node, with its keys.
function metas(schema, parameters, places) {
  const byName = new Map();
  const groups = new Map();
  const rules = new Map();  // parameter name -> the rules that read it
  for (const described of schema?.classes || []) {
    for (const rule of described.rules || [])
      for (const name of rule.parameters) rules.set(name, [...(rules.get(name) || []), rule]);
  }
  for (const described of schema?.classes || []) {
    for (const p of described.parameters)
      byName.set(p.name, { ...p, schema: true, rules: rules.get(p.name) || [] });
    for (const group of described.maps) groups.set(group.path, group);
  }
  const values = new Map(parameters.map((p) => [p.name, p.value]));
  const shown = [];
  for (const place of places || []) {
    const group = groups.get(place.map);
    if (!group) continue;
    shown.push({ ...place, group });
    const fields = new Map(group.fields.map((f) => [f.name, f]));
    for (const key of place.keys) {
      for (const field of place.fields)
        byName.set(entryName(place, key, field), { ...fields.get(field), schema: true, mapped: place.path, key });
    }
  }
  for (const p of parameters) {
    const known = byName.get(p.name);
    // A parameter of type any is edited in the type of its current value.
    if (known?.type === "any" && p.type !== "unset") byName.set(p.name, { ...known, type: p.type });
    if (known) continue;
    byName.set(p.name, { name: p.name, type: p.type, read_only: p.read_only, range: p.range,
      description: p.description, constraints: p.constraints ? [p.constraints] : [], schema: false });
  }
  return { byName, places: shown, values };
}

function namespaceOf(name) {
  const dot = name.lastIndexOf(".");
  return dot < 0 ? "" : name.slice(0, dot);
}

function showError(name, text) {
  const box = page.view?.form.querySelector(`[data-param-error="${CSS.escape(name)}"]`);
  if (box) box.textContent = text || "";
}

function setControl(name, value) {
  const control = page.view?.form.querySelector(`[data-param="${CSS.escape(name)}"]`);
  control?.genparamsSet?.(value);
}

function renderDiff() {
  const { byName, values } = page.view.known;
  const rows = [];
  for (const [name, meta] of byName) {
    if (!meta.schema || meta.required || meta.optional || !values.has(name)) continue;
    if (stringifyJson(meta.default) !== stringifyJson(values.get(name)))  // NaN equals NaN, inf is not -inf
      rows.push([name, meta.default, values.get(name), meta.type]);
  }
  page.view.diff.replaceChildren(diffTable(rows));
}

function showNote(name, attribute, text) {
  const box = page.view?.form.querySelector(`[${attribute}="${CSS.escape(name)}"]`);
  if (box) box.textContent = text || "";
}

// The server's answer, row by row: the node's reason, and the checks only the node can run.
function showVerdicts(check) {
  for (const result of check.results) {
    markRow(result.name, result.successful ? "ok" : "refused");
    showError(result.name, result.successful ? "" : result.reason);
    showNote(result.name, "data-param-note", result.not_checked.join(" · "));
  }
}

// Each row says where its value stands: checking, ok, refused, working (sent, not answered)
// or unknown (its node left before answering) (data-verdict).
function markRow(name, verdict) {
  const row = page.view?.form.querySelector(`[data-row="${CSS.escape(name)}"]`);
  if (row) row.dataset.verdict = verdict;
}

// Edits as the API takes them; a value the page could not type is shown and not sent.
function typedEdits(edits) {
  const params = [];
  let typed = true;
  for (const [name, value] of edits) {
    if (value instanceof InputError) {
      showError(name, `${name}: ${value.message}`);
      markRow(name, "refused");
      typed = false;
      continue;
    }
    params.push({ name, type: page.view.known.byName.get(name).type, value });
  }
  return typed ? params : null;
}

async function applyEdits(edits, atomic) {
  const params = typedEdits(edits);
  if (!params || !params.length) return false;
  const node = page.node;
  const check = await api.check(node, params).catch(() => null);  // unreachable: the node decides
  if (node !== page.node) return false;
  if (check) {
    showVerdicts(check);
    if (!check.successful) { status("the node would refuse this change: not sent"); return false; }
  }
  clearTimeout(page.checkTimer);
  page.checks++;  // a check still in flight answers for values before this set: not shown
  const answer = await api.set(node, params, atomic);
  if (node !== page.node) return false;
  if (answer.pending) { awaitOutcome(node, answer, edits); return "sent"; }
  return showResults(answer.results, `applied ${params.length} change(s)`);
}

// A set's results, row by row; true when the node took every value.
function showResults(results, applied) {
  let ok = true;
  for (const result of results) {
    showError(result.name, result.successful ? "" : result.reason || "rejected by the node");
    showNote(result.name, "data-param-note", "");
    markRow(result.name, result.successful ? "ok" : "refused");
    ok &&= result.successful;
  }
  status(ok ? applied : "the node rejected the change");
  return ok;
}

// The node has not answered the set yet (it was sent once and is not sent again): its rows
// say so until its "set" event tells the outcome, or a new read of the node replaces them.
function awaitOutcome(node, answer, edits) {
  page.unconfirmed.set(answer.set, { node, edits: new Map(edits) });
  for (const [name] of edits) {
    markRow(name, "working");
    showNote(name, "data-param-note", "sent, not yet confirmed by the node");
  }
  status(answer.detail);
}

// The outcome of a set the node was still working on. A value it refused goes back to the
// edits not applied, unless it was edited again meanwhile.
function onSetOutcome(event) {
  const sent = page.unconfirmed.get(event.set);
  if (!sent || sent.node !== event.node) return;
  page.unconfirmed.delete(event.set);
  if (!page.view || event.node !== page.node) return;
  if (event.error) {  // no usable answer: refused, or unknown when the node left unanswering
    const verdict = event.unknown ? "unknown" : "refused";
    const said = event.unknown ? "outcome unknown: the node left before answering" : "";
    for (const [name] of sent.edits) { markRow(name, verdict); showNote(name, "data-param-note", said); }
    status(`${event.node}: ${event.error}`);
    return;
  }
  const ok = showResults(event.results, `${event.node} applied ${sent.edits.size} change(s)`);
  if (ok) return;
  for (const [name, value] of sent.edits) if (!page.pending.has(name)) page.pending.set(name, value);
  updateApplyButton();
}

// Check the edits not applied yet, with what is being typed, a moment after the last key.
function scheduleCheck() {
  clearTimeout(page.checkTimer);
  page.checkTimer = setTimeout(checkEdits, CHECK_DELAY_MS);
}

async function checkEdits() {
  if (!page.view) return;
  const edits = new Map([...page.pending, ...page.drafts]);
  page.drafts.clear();
  const params = typedEdits(edits);
  if (!params || !params.length) return;
  const node = page.node;
  const asked = ++page.checks;  // an answer to an older question is not shown
  const check = await api.check(node, params).catch(() => null);
  if (check && node === page.node && asked === page.checks) showVerdicts(check);
}

function onDraft(name, value) {
  page.drafts.set(name, value);
  markRow(name, "checking");
  scheduleCheck();
}

function onEdit(name, value) {
  page.drafts.delete(name);
  markRow(name, "checking");
  if (liveMode()) {
    applyEdits([[name, value]], false).then((ok) => {
      if (!ok && !page.pending.has(name)) page.pending.set(name, value);
      updateApplyButton();
    });
    return;
  }
  page.pending.set(name, value);
  updateApplyButton();
  scheduleCheck();
}

function updateApplyButton() {
  if (!page.view) return;
  page.view.apply.textContent = `Apply ${page.pending.size} change(s) atomically`;
  page.view.apply.disabled = page.readOnly || page.pending.size === 0;
}

// An apply sends the pending edits; the node may change any of them meanwhile (another
// tab, another tool). Once applied, each row shows the last value the node announced, so
// the form never keeps a value the node no longer holds.
async function applyPending() {
  const sent = new Map(page.pending);
  const applying = { changed: new Set() };
  page.applying = applying;
  let ok = false;
  try {
    ok = await applyEdits([...sent], true);
  } finally {
    if (page.applying === applying) page.applying = null;
  }
  if (!ok || !page.view) return;  // ok: true, or "sent" (the node is still working on it)
  for (const [name, value] of sent) {
    if (stringifyJson(page.pending.get(name)) !== stringifyJson(value)) continue;  // edited again
    page.pending.delete(name);
    showNote(name, "data-param-node", "");
    if (applying.changed.has(name)) setControl(name, page.view.known.values.get(name));
  }
  updateApplyButton();
}

function onReset(name) {
  const meta = page.view.known.byName.get(name);
  setControl(name, meta.default);
  onEdit(name, meta.default);
}

function setKeys(group, keys) {
  applyEdits([[group.for_each, keys]], false);
}

function renderNode(data) {
  page.pending.clear();
  page.unconfirmed.clear();  // the values are the node's, as just read
  const known = metas(data.schema, data.parameters, data.places);
  page.drafts.clear();
  const handlers = { readOnly: page.readOnly, onEdit, onDraft, onReset };
  const rowFor = (name) => {
    const meta = known.byName.get(name);
    const label = meta.key !== undefined ? meta.name || meta.key : name.slice(namespaceOf(name).length + (namespaceOf(name) ? 1 : 0));
    return row(meta, name, label, known.values.get(name), { ...handlers, hasDefault: meta.schema && !meta.required && !meta.optional });
  };
  const sections = new Map();
  for (const name of [...known.values.keys()].sort()) {
    const meta = known.byName.get(name);
    if (meta.mapped !== undefined) continue;
    const title = meta.schema ? namespaceOf(name) : "other parameters (not in the schema)";
    if (!sections.has(title)) sections.set(title, []);
    sections.get(title).push(name);
  }
  const order = [...sections.keys()].sort((a, b) => (a.startsWith("other") - b.startsWith("other")) || a.localeCompare(b));
  // Builders, each with its row count: the first screenful is built at once, the rest in chunks.
  const builders = order.map((t) => [sections.get(t).length, () => section(t, sections.get(t).map(rowFor))]);
  for (const place of known.places) {
    builders.push([place.keys.length * place.fields.length, () => mapGroup(place,
      (key) => place.fields.map((f) => rowFor(entryName(place, key, f))),
      { readOnly: page.readOnly,
        onAddKey: (g, key) => setKeys(g, [...(known.values.get(g.for_each) || []), key]),
        onRemoveKey: (g, key) => setKeys(g, (known.values.get(g.for_each) || []).filter((k) => k !== key)) })]);
  }
  const apply = el("button", { type: "button", "data-apply": true });
  apply.addEventListener("click", applyPending);
  const download = el("a", { href: api.paramsFileUrl(data.node), download: "", "data-download": true,
    text: "Download params file" });
  const diff = el("div", { class: "diff-box" });
  const body = el("div", { class: "sections" });
  const kind = data.schema ? `genparams ${data.schema.genparams} · schema ${data.schema.hash}` : "plain rclpy node";
  // A schema message that is malformed or not the node's own is shown, never used.
  const refused = data.schema_problem
    ? el("p", { class: "schema-problem", "data-schema-problem": true, text: `schema not used: ${data.schema_problem}` })
    : null;
  const form = el("form", { "data-node": data.node, class: data.schema ? "genparams" : "plain" },
    el("h2", { text: data.node }), el("p", { class: "hint", text: kind }), refused,
    el("div", { class: "toolbar" }, apply, download, keepControls(data.node, page.readOnly)), body,
    el("h3", { text: "Differences from the defaults" }), diff);
  form.addEventListener("submit", (event) => event.preventDefault());
  page.view = { form, known, apply, diff, shape: shapeOf(data) };
  buildInChunks(body, builders, form);
  document.getElementById("view").replaceChildren(form);
  updateApplyButton();
  renderDiff();
}

// Append sections until `budget` rows are in; the rest follow in chunks, a frame apart,
// so a node with thousands of parameters is usable before its last section exists.
function buildInChunks(body, builders, form, budget = 60) {
  let next = 0;
  const step = (limit) => {
    let rows = 0;
    while (next < builders.length && (rows === 0 || rows + builders[next][0] <= limit)) {
      rows += builders[next][0];
      body.append(builders[next++][1]());
    }
  };
  step(budget);
  return new Promise((resolve) => {
    const more = () => {
      if (page.view?.form !== form) return resolve();
      if (next >= builders.length) {
        form.dataset.complete = String(Math.round(performance.now()));
        return resolve();
      }
      step(200);
      setTimeout(more);
    };
    requestAnimationFrame(() => setTimeout(more));
  });
}

// A read is a snapshot: a change the node makes while it is in flight may be older or
// newer than it. Events of a node being read for a new form are held back (page.missed)
// and the node is read once more when the form shows; a catch-up read of a form already
// shown lets events through and keeps them over its own older values.
async function openNode(name, loading = null) {
  page.node = name;
  for (const item of document.querySelectorAll("#nodes li"))
    item.classList.toggle("selected", item.dataset.nodeLink === name);
  status(`loading ${name}…`);
  const data = await newest(name, loading || api.node(name), true);
  if (data === null || page.node !== name) return;  // another read or node took over
  renderNode(data);  // later sections follow on their own; the form says data-complete
  status(`${data.parameters.length} parameters`);
  if (page.missed) catchUp(name).catch(failed(name));
}

// A read of `name`; null when a later read started meanwhile (only the newest counts).
// `hold`: the node's events wait in page.missed until it is in.
async function newest(name, read, hold = false) {
  const id = ++page.reads;
  if (hold) { page.loading = name; page.missed = false; }
  try {
    const data = await read;
    return id === page.reads ? data : null;
  } finally {
    if (id === page.reads) page.loading = null;
  }
}

const failed = (name) => (error) => status(`${name}: ${error.message}`);

// What the form is built from, but the values: the schema (or why it is not used), the
// places of mapped groups and the parameters' names.
const shapeOf = (data) => stringifyJson([data.schema ?? null, data.schema_problem ?? null,
  data.places ?? null, data.parameters.map((p) => p.name).sort()]);

// Read the open node again and take in what changed since, as an event would; a value an
// event brought during the read is newer than the read's. Any other difference (a schema,
// a parameter more or less) builds the form anew.
async function catchUp(name) {
  const fresher = new Set();
  page.fresher = fresher;
  const data = await newest(name, api.node(name));
  if (page.fresher === fresher) page.fresher = null;
  if (data === null || page.node !== name || !page.view) return;
  if (shapeOf(data) !== page.view.shape) return openNode(name);
  const known = page.view.known.values;
  const changed = {};
  for (const p of data.parameters) {
    if (!fresher.has(p.name) && stringifyJson(p.value) !== stringifyJson(known.get(p.name)))
      changed[p.name] = p.value;
  }
  onEvent({ node: name, changed });
}

function onEvent(event) {
  if (event.kind === "set") { onSetOutcome(event); return; }
  if (event.node === page.loading) { page.missed = true; return; }  // read again once shown
  if (!page.view || event.node !== page.node) return;
  if (event.kind === "schema" || Object.keys(event.new || {}).length || (event.deleted || []).length) {
    clearTimeout(page.reload);  // the set of parameters changed: build the form again
    page.reload = setTimeout(() => openNode(page.node).catch(failed(page.node)), 200);  // one event per declare
    return;
  }
  for (const [name, value] of Object.entries(event.changed || {})) {
    page.fresher?.add(name);
    page.view.known.values.set(name, value);
    page.applying?.changed.add(name);
    if (!page.pending.has(name)) { setControl(name, value); showError(name, ""); }
    else showNote(name, "data-param-node",
      `the node now holds ${shownJson(value, page.view.known.byName.get(name)?.type)}`);
  }
  renderDiff();
}

async function refreshNodes() {
  const { nodes } = await api.nodes();
  const list = document.getElementById("nodes");
  const shown = [...list.children].map((li) => `${li.dataset.nodeLink}|${li.dataset.genparams}|${li.title}`).join();
  if (shown === nodes.map((n) => `${n.name}|${n.genparams}|${n.schema_problem || ""}`).join()) return;
  list.replaceChildren(...nodes.map((n) => {
    const link = el("a", { href: `#${n.name}`, text: n.name });
    link.addEventListener("click", () => openNode(n.name).catch(failed(n.name)));
    const badge = n.schema_problem ? el("span", { class: "badge schema-problem", text: "bad schema" })
      : n.genparams ? el("span", { class: "badge", text: "schema" }) : null;
    return el("li", { "data-node-link": n.name, "data-genparams": String(n.genparams),
      title: n.schema_problem || "", class: n.name === page.node ? "selected" : "" }, link, badge);
  }));
}

// The node named after "#" in the address; a fragment that does not decode names none.
function nodeInAddress() {
  try {
    return decodeURIComponent(window.location.hash.slice(1));
  } catch {
    status("the address names no node (its # part does not decode)");
    return "";
  }
}

// Events of the open node. Whatever changed before the stream opened is not in it: the
// open node is read again then, the first time as after a reconnect (the server drops a
// stream that falls too far behind, and the browser reconnects).
function listen() {
  const events = api.events();
  let opened = 0;
  events.onopen = () => {
    document.body.dataset.listening = "";  // from now on the page follows changes
    const first = opened++ === 0;
    if (!page.node) return;
    if (!first) openNode(page.node).catch(failed(page.node));
    else if (page.loading === page.node) page.missed = true;
    else if (page.view) catchUp(page.node).catch(failed(page.node));
  };
  events.onmessage = (message) => onEvent(parseJson(message.data));
}

async function main() {
  // The node named in the address loads while the config and the node list are fetched.
  const wanted = nodeInAddress();
  const loading = wanted ? api.node(wanted) : null;
  loading?.catch(() => {});  // openNode reports it
  const config = await api.config();
  page.readOnly = config.read_only;
  document.getElementById("mode").hidden = !page.readOnly;
  listen();
  await Promise.all([
    refreshNodes(),
    wanted ? openNode(wanted, loading).catch((error) => status(`${wanted}: ${error.message}`)) : null,
  ]);
  setInterval(refreshNodes, 1000);
  // Milliseconds from navigation to a usable page, after the first paint of the form.
  await new Promise((resolve) => requestAnimationFrame(() => setTimeout(resolve)));
  document.body.dataset.ready = String(Math.round(performance.now()));
}

main().catch((error) => status(`error: ${error.message}`));
