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

// An int64 past 2^53 is read from its own digits as a BigInt: a double would round it.
// (A double is written with a point or an exponent, so digits alone are an integer.)
const INTEGER = /^-?\d+$/;
function exactNumber(value, context) {
  if (typeof value !== "number" || Number.isSafeInteger(value)) return value;
  const source = context?.source;  // JSON.parse source text access
  return typeof source === "string" && INTEGER.test(source) && JSON.rawJSON ? BigInt(source) : value;
}

export function parseJson(text) {
  return JSON.parse(text, (key, value, context) =>
    (isFloatTag(value) ? FLOATS[value.$float] : exactNumber(value, context)));
}

export function stringifyJson(value) {
  return JSON.stringify(value, (key, item) => {
    // A browser without JSON.rawJSON never makes a BigInt here (see exactNumber, numberOf).
    if (typeof item === "bigint") return JSON.rawJSON ? JSON.rawJSON(String(item)) : Number(item);
    const name = floatName(item);
    return name === undefined ? item : { $float: name };
  });
}

// A number as the page shows it: nan, inf and -inf by name, a double with its point (30.0,
// as ROS tells 30.0 from 30), an integer with all its digits.
export function numberText(value, type = "") {
  const name = floatName(value);
  if (name !== undefined) return name;
  if (type.startsWith("double") && Number.isInteger(value) && Math.abs(value) < 1e21)
    return value.toFixed(1);
  return String(value ?? "");
}

// A value as the page shows it: JSON, with numbers as numberText shows them (never null).
export function shownJson(value, type = "") {
  if (typeof value === "number" || typeof value === "bigint") return numberText(value, type);
  if (Array.isArray(value)) return `[${value.map((item) => shownJson(item, type)).join(", ")}]`;
  return JSON.stringify(value);
}
