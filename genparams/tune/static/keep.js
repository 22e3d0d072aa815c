// "Keep these values": the server shows what it would write into the params files given to
// `genparams tune --params-file`, as a diff; a second click writes it. Text nodes only.
import { api } from "./api.js";
import { el } from "./form.js";

export function keepControls(node, readOnly) {
  const keep = el("button", { type: "button", "data-keep": true, text: "Keep these values" });
  const write = el("button", { type: "button", "data-keep-write": true, text: "Write to the files" });
  const shown = el("pre", { class: "keep-diff", "data-keep-diff": true });
  const status = el("p", { class: "hint", "data-keep-status": true });
  write.hidden = true;
  keep.disabled = readOnly;
  keep.addEventListener("click", async () => {
    status.textContent = "";
    try {
      const preview = await api.keepPreview(node);
      shown.textContent = preview.diff || "The files already hold every value.";
      write.hidden = !preview.diff;
    } catch (error) {
      status.textContent = `cannot keep: ${error.message}`;
    }
  });
  write.addEventListener("click", async () => {
    try {
      const done = await api.keep(node);
      status.textContent = `kept: ${done.changes.length} value(s) written`;
      write.hidden = true;
    } catch (error) {
      status.textContent = `cannot keep: ${error.message}`;
    }
  });
  return el("span", { class: "keep" }, keep, write, shown, status);
}
