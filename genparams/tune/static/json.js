// The tuning API's JSON (docs/tuning.md, "JSON and non-finite numbers"): JSON has no NaN or
// infinity, so the server writes them as {"$float": "nan" | "inf" | "-inf"}; so does the page.
const FLOATS = { nan: NaN, inf: Infinity, "-inf": -Infinity };

function isFloatTag(value) {
  return value !== null && typeof value === "object" && !Array.isArray(value)
    && Object.keys(value).length === 1 && Object.hasOwn(FLOATS, value.$float);
}

export function parseJson(text) {
  return JSON.parse(text, (key, value) => (isFloatTag(value) ? FLOATS[value.$float] : value));
}

export function stringifyJson(value) {
  return JSON.stringify(value, (key, item) => {
    if (typeof item !== "number" || Number.isFinite(item)) return item;
    return { $float: Number.isNaN(item) ? "nan" : item > 0 ? "inf" : "-inf" };
  });
}
