// Calls to the tuning server. The page's URL carries the token once: the server answers it
// with an HttpOnly, SameSite=Strict cookie that goes with every later call, and the token
// leaves the address bar (and so the history, bookmarks and screen shares) at once.
// Every JSON body, both ways, goes through json.js (NaN and infinities as tags).
import { parseJson, stringifyJson } from "./json.js";

function forgetToken() {
  const url = new URL(window.location.href);
  if (!url.searchParams.has("token")) return;
  url.searchParams.delete("token");
  window.history.replaceState(window.history.state, "", `${url.pathname}${url.search}${url.hash}`);
}
forgetToken();

async function call(path, options = {}) {
  const response = await fetch(path, { ...options, credentials: "same-origin" });
  const body = await response.text().then(parseJson).catch(() => ({}));
  if (!response.ok) throw new Error(body.error || response.statusText);
  return body;
}

export const api = {
  config: () => call("/api/config"),
  nodes: () => call("/api/nodes"),
  node: (name) => call(`/api/node?name=${encodeURIComponent(name)}`),
  set: (node, params, atomic) =>
    call("/api/set", {
      method: "POST",
      headers: { "content-type": "application/json" },
      body: stringifyJson({ node, params, atomic }),
    }),
  // What the node would answer to setting `params` together, without setting them.
  check: (node, params) =>
    call("/api/check", {
      method: "POST",
      headers: { "content-type": "application/json" },
      body: stringifyJson({ node, params }),
    }),
  keepPreview: (node) => call(`/api/keep?node=${encodeURIComponent(node)}`),
  keep: (node) => call("/api/keep", { method: "POST", headers: { "content-type": "application/json" }, body: stringifyJson({ node }) }),
  paramsFileUrl: (name) => `/api/params-file?node=${encodeURIComponent(name)}`,
  events: () => new EventSource("/api/events"),
};
