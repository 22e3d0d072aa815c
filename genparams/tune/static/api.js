// Calls to the tuning server. A token given in the page's URL goes with every call.
import { parseJson, stringifyJson } from "./json.js";

const token = new URLSearchParams(window.location.search).get("token");

export function withToken(path) {
  if (!token) return path;
  const sep = path.includes("?") ? "&" : "?";
  return `${path}${sep}token=${encodeURIComponent(token)}`;
}

async function call(path, options = {}) {
  const headers = { ...(options.headers || {}) };
  if (token) headers["x-genparams-token"] = token;
  const response = await fetch(path, { ...options, headers });
  const body = parseJson(await response.text());
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
  paramsFileUrl: (name) => withToken(`/api/params-file?node=${encodeURIComponent(name)}`),
  events: () => new EventSource(withToken("/api/events")),
};
