// The tuning API's JSON (docs/tuning.md, "JSON and non-finite numbers"): JSON has no NaN or
// infinity, so the server writes them as {"$float": "nan" | "inf" | "-inf"}; so does the page.
// The same three names are how the page shows such a number and how one is typed.
const FLOATS = { nan: NaN, inf: Infinity, "-inf": -Infinity };

function isFloatTag(value) {
  return value !== null && typeof value === "object" && !Array.isArray(value)
    && Object.keys(value).length === 1 && Object.hasOwn(FLOATS, value.$float);
}

// The codec's name of a number that is not finite ("nan", "inf", "-inf"), else undefined.
export function floatName(number) {
  if (typeof number !== "number" || Number.isFinite(number)) return undefined;
  return Number.isNaN(number) ? "nan" : number > 0 ? "inf" : "-inf";
}

// The number a codec name stands for ("nan", "inf", "-inf", any case), else undefined.
export function namedFloat(text) {
  const name = String(text).trim().toLowerCase();
  return Object.hasOwn(FLOATS, name) ? FLOATS[name] : undefined;
}

export function parseJson(text) {
  return JSON.parse(text, (key, value) => (isFloatTag(value) ? FLOATS[value.$float] : value));
}

export function stringifyJson(value) {
  return JSON.stringify(value, (key, item) => {
    const name = floatName(item);
    return name === undefined ? item : { $float: name };
  });
}

// A value as the page shows it: JSON, with nan, inf and -inf as such (never null).
export function shownJson(value) {
  const name = floatName(value);
  if (name !== undefined) return name;
  if (Array.isArray(value)) return `[${value.map(shownJson).join(", ")}]`;
  return JSON.stringify(value);
}
