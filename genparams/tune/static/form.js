// A node's form: one section per namespace, one row per parameter, a fieldset per mapped group.
// The page only types what the user enters as JSON; every rule is checked by the server
// (the node's own checks, /api/check) and by the node.
import { namedFloat, numberText, shownJson } from "./json.js";

export function isArrayType(type) {
  return type.endsWith("_array");
}

export function elementType(type) {
  return { byte_array: "byte", bool_array: "bool", int_array: "int",
    double_array: "double", string_array: "string" }[type] || type;
}

// Text that is not a JSON number: the row says so and nothing is sent.
export class InputError {
  constructor(message) { this.message = message; }
}

function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attrs)) {
    if (value === undefined || value === null || value === false) continue;
    if (key === "text") node.textContent = value;
    else if (key.startsWith("data-") || key === "for" || key === "title" || key === "class")
      node.setAttribute(key, value === true ? "" : value);
    else node[key] = value;
  }
  node.append(...children.filter((c) => c !== null && c !== undefined));
  return node;
}

// The number the user typed, as typed: 2.5 stays 2.5 for an integer (the server refuses it).
// nan, inf and -inf are the codec's names (json.js); a number too large for a double is not one.
function numberOf(kind, text) {
  const trimmed = String(text).trim();
  if (trimmed === "") return new InputError("enter a number");
  const named = namedFloat(trimmed);
  if (named !== undefined) return named;
  const value = Number(trimmed);
  if (!Number.isFinite(value)) {
    return new InputError(`${JSON.stringify(trimmed)} is not a number (nan, inf and -inf are)`);
  }
  // An integer past 2^53 keeps its digits: a BigInt, written as typed (json.js).
  if (/^-?\d+$/.test(trimmed) && !Number.isSafeInteger(value) && JSON.rawJSON) return BigInt(trimmed);
  return value;
}

// A double's box is text, so that it can hold nan, inf and -inf; an int's is a number box.
function numberInput(kind, value, step, attrs) {
  if (kind === "double") return el("input", { type: "text", inputMode: "decimal", value: numberText(value, kind), ...attrs });
  return el("input", { type: "number", step, value: numberText(value, kind), ...attrs });
}

function scalarInput(kind, value, attrs) {
  if (kind === "bool") return el("input", { type: "checkbox", checked: Boolean(value), ...attrs });
  if (kind === "string") return el("input", { type: "text", value: value ?? "", ...attrs });
  return numberInput(kind, value, "1", attrs);
}

function scalarValue(kind, input) {
  if (kind === "bool") return input.checked;
  if (kind === "string") return input.value;
  return numberOf(kind, input.value);
}

// Array editors: one typed input per item, with add and remove.
function arrayEditor(meta, name, value, disabled, onEdit) {
  const kind = elementType(meta.type);
  const box = el("div", { class: "array", "data-param": name, "data-type": meta.type });
  const items = el("div", { class: "items" });
  const read = () => {
    const values = [...items.querySelectorAll("input")].map((input) => scalarValue(kind, input));
    const bad = values.findIndex((v) => v instanceof InputError);
    return bad < 0 ? values : new InputError(`item ${bad}: ${values[bad].message}`);
  };
  const addItem = (item) => {
    const input = scalarInput(kind, item, { disabled });
    input.addEventListener("change", () => onEdit(name, read()));
    const remove = el("button", { type: "button", class: "small", text: "−", title: "remove item", disabled });
    remove.addEventListener("click", () => { row.remove(); onEdit(name, read()); });
    const row = el("div", { class: "item" }, input, remove);
    items.append(row);
  };
  (value || []).forEach(addItem);
  const add = el("button", { type: "button", class: "small", text: "+ item", disabled });
  add.addEventListener("click", () => { addItem(kind === "bool" ? false : kind === "string" ? "" : 0); });
  box.append(items, add);
  box.genparamsSet = (next) => { items.replaceChildren(); (next || []).forEach(addItem); };
  return box;
}

function control(meta, name, value, disabled, onEdit, onDraft) {
  const kind = meta.type;
  if (isArrayType(kind)) return arrayEditor(meta, name, value, disabled, onEdit);
  const id = `p-${name}`;
  if (meta.choices) {
    const shown = (c) => (kind === "string" ? String(c) : numberText(c, kind));
    const select = el("select", { id, "data-param": name, disabled },
      ...meta.choices.map((c) => el("option", { value: shown(c), text: shown(c) })));
    select.value = shown(value);
    const parse = (text) => (kind === "string" ? text : numberOf(kind, text));
    select.addEventListener("change", () => onEdit(name, parse(select.value)));
    select.genparamsSet = (next) => { select.value = shown(next); };
    return select;
  }
  if ((kind === "int" || kind === "double") && meta.range) {
    const { min, max, step } = meta.range;
    const sliderStep = step > 0 ? step : kind === "int" ? 1 : (max - min) / 1000;
    const slider = el("input", { id, type: "range", min, max, step: sliderStep, value, disabled, "data-param": name });
    const number = numberInput(kind, value, step > 0 ? step : 1, { disabled, "data-param-box": name });
    slider.addEventListener("input", () => { number.value = slider.value; });
    slider.addEventListener("change", () => onEdit(name, numberOf(kind, slider.value)));
    number.addEventListener("change", () => {
      slider.value = number.value;
      onEdit(name, numberOf(kind, number.value));
    });
    number.addEventListener("input", () => onDraft(name, numberOf(kind, number.value)));
    const pair = el("span", { class: "slider" }, slider, number);
    slider.genparamsSet = (next) => { slider.value = next; number.value = numberText(next, kind); };
    pair.genparamsControl = slider;
    return pair;
  }
  const input = scalarInput(kind, value, { id, disabled, "data-param": name });
  input.addEventListener("change", () => onEdit(name, scalarValue(kind, input)));
  if (kind !== "bool") input.addEventListener("input", () => onDraft(name, scalarValue(kind, input)));
  input.genparamsSet = (next) => {
    if (kind === "bool") input.checked = Boolean(next); else input.value = kind === "string" ? next : numberText(next, kind);
  };
  return input;
}

function help(meta) {
  const words = [meta.description, ...(meta.constraints || [])].filter(Boolean);
  if (meta.deprecated) words.push(`deprecated: ${meta.deprecated}`);
  return words.join(" · ");
}

// The cross-parameter rules that read this parameter, one line each.
function rulesOf(meta) {
  return el("ul", { class: "rules", "data-param-rules": meta.name },
    ...(meta.rules || []).map((rule) => el("li", { "data-rule": rule.name,
      text: `rule ${rule.name}: ${rule.check}${rule.description ? ` (${rule.description})` : ""}` })));
}

export function row(meta, name, label, value, { readOnly, onEdit, onDraft, onReset, hasDefault }) {
  const disabled = readOnly || meta.read_only;
  const widget = control(meta, name, value, disabled, onEdit, onDraft);
  const reset = hasDefault
    ? el("button", { type: "button", class: "reset small", text: "↺", title: "reset to default",
        "data-reset": name, disabled })
    : null;
  reset?.addEventListener("click", () => onReset(name));
  return el("div", { class: "param", "data-row": name },
    el("label", { for: `p-${name}`, title: name },
      label, meta.required ? el("span", { class: "required", title: "required", text: " *" }) : null),
    widget,
    el("span", { class: "unit", text: meta.unit || "" }),
    reset,
    el("div", { class: "error", "data-param-error": name, role: "alert" }),
    el("div", { class: "note", "data-param-note": name }),
    el("div", { class: "note", "data-param-node": name }),
    meta.rules?.length ? rulesOf({ ...meta, name }) : null,
    el("div", { class: "help", text: help(meta) }));
}

export function section(title, rows) {
  return el("fieldset", { class: "section", "data-section": title },
    el("legend", { text: title || "(top level)" }), ...rows);
}

// One place of a mapped group (places.py): its entries, and for a group keyed by a list the
// buttons that set the list. An open group's keys are the names the node declared under it
// at startup: none can be added or removed.
export function mapGroup(place, keyRows, { readOnly, onAddKey, onRemoveKey }) {
  const { group, path } = place;
  const entries = place.keys.map((key) => {
    const where = path ? `${path}.${key}` : key;
    const remove = place.open ? null : el("button", { type: "button", class: "small", text: "remove key",
      "data-map-remove": where, disabled: readOnly });
    remove?.addEventListener("click", () => onRemoveKey(group, key));
    return el("fieldset", { class: "entry", "data-entry": where },
      el("legend", {}, `${where} `, remove), ...keyRows(key));
  });
  const title = place.open
    ? `${path} (one entry per key given under ${path} in the overrides)`
    : `${path || "(top level)"} (one entry per item of ${group.for_each})`;
  const box = el("fieldset", { class: "section map", "data-map": path, "data-open": place.open },
    el("legend", { text: title }), ...entries);
  if (place.open) {
    if (!place.keys.length) box.append(el("p", { class: "hint", text: "No key was given in the overrides." }));
    return box;
  }
  const input = el("input", { type: "text", placeholder: "new key", "data-map-add": path, disabled: readOnly });
  const add = el("button", { type: "button", class: "small", text: "add key",
    "data-map-add-button": path, disabled: readOnly });
  add.addEventListener("click", () => { if (input.value) onAddKey(group, input.value); });
  box.append(el("div", { class: "add-key" }, input, add));
  return box;
}

export function diffTable(rows) {
  if (!rows.length) return el("p", { class: "hint", "data-diff-empty": true, text: "All values are at their defaults." });
  return el("table", { class: "diff" },
    el("thead", {}, el("tr", {}, ...["parameter", "default", "current"].map((t) => el("th", { text: t })))),
    el("tbody", {}, ...rows.map(([name, def, cur, type]) => el("tr", { "data-diff": name },
      el("td", { text: name }), el("td", { text: shownJson(def, type) }), el("td", { text: shownJson(cur, type) })))));
}

export { el };
