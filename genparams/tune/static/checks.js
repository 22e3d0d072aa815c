// The schema's checks, run in the page before anything is sent. The node checks
// again (and alone checks rules and custom validators): its reason is the last word.

const INT64_MAX = 2n ** 63n - 1n;
const EPSILON = 1e-9;

export function isArrayType(type) {
  return type.endsWith("_array");
}

export function elementType(type) {
  return { byte_array: "byte", bool_array: "bool", int_array: "int",
    double_array: "double", string_array: "string" }[type] || type;
}

function typeProblem(kind, value) {
  if (kind === "bool") return typeof value === "boolean" ? null : "must be true or false";
  if (kind === "string") return typeof value === "string" ? null : "must be a string";
  if (typeof value !== "number" || !Number.isFinite(value)) return "must be a number";
  if (kind === "int" && !Number.isInteger(value)) return "must be an integer";
  if (kind === "int" && (BigInt(Math.trunc(value)) > INT64_MAX || BigInt(Math.trunc(value)) < -INT64_MAX - 1n))
    return "is outside int64";
  if (kind === "byte" && (!Number.isInteger(value) || value < 0 || value > 255))
    return "must be a byte (0 to 255)";
  return null;
}

function rangeProblem(range, value) {
  if (value < range.min || value > range.max)
    return `${value} is not within [${range.min}, ${range.max}]`;
  if (range.step > 0 && value !== range.max) {
    const steps = (value - range.min) / range.step;
    if (Math.abs(steps - Math.round(steps)) > EPSILON * Math.max(1, Math.abs(steps)))
      return `${value} is not ${range.min} plus a multiple of the step ${range.step}`;
  }
  return null;
}

function same(a, b) {
  return JSON.stringify(a) === JSON.stringify(b);
}

const VALIDATORS = {
  gt: (v, a) => (v > a ? null : `must be > ${a}`),
  ge: (v, a) => (v >= a ? null : `must be >= ${a}`),
  lt: (v, a) => (v < a ? null : `must be < ${a}`),
  le: (v, a) => (v <= a ? null : `must be <= ${a}`),
  bounds: (v, a) => (v >= a[0] && v <= a[1] ? null : `must be within [${a[0]}, ${a[1]}]`),
  element_bounds: (v, a) =>
    v.every((x) => x >= a[0] && x <= a[1]) ? null : `every item must be within [${a[0]}, ${a[1]}]`,
  one_of: (v, a) => (a.some((c) => same(c, v)) ? null : `must be one of ${JSON.stringify(a)}`),
  subset_of: (v, a) =>
    v.every((x) => a.some((c) => same(c, x))) ? null : `every item must be one of ${JSON.stringify(a)}`,
  not_empty: (v) => (v.length > 0 ? null : "must not be empty"),
  unique: (v) => (new Set(v.map((x) => JSON.stringify(x))).size === v.length ? null : "has repeated items"),
  length: (v, a) => {
    const limits = typeof a === "number" ? { min: a, max: a } : { min: a.exact ?? a.min, max: a.exact ?? a.max };
    if (limits.min !== undefined && v.length < limits.min) return `must have length >= ${limits.min}`;
    if (limits.max !== undefined && v.length > limits.max) return `must have length <= ${limits.max}`;
    return null;
  },
  pattern: (v, a) => {
    let re;
    try { re = new RegExp(a, "u"); } catch { return null; } // Python-only syntax: the node decides
    const items = Array.isArray(v) ? v : [v];
    const bad = items.find((x) => !re.test(x));
    return bad === undefined ? null : `${JSON.stringify(bad)} does not match ${JSON.stringify(a)}`;
  },
};

// Why `value` breaks `meta` (a schema parameter or a descriptor), or null.
export function problem(meta, value) {
  const kind = elementType(meta.type);
  const items = isArrayType(meta.type) ? value : [value];
  if (!Array.isArray(items)) return "must be a list";
  for (const item of items) {
    const bad = typeProblem(kind, item);
    if (bad) return isArrayType(meta.type) ? `item ${JSON.stringify(item)} ${bad}` : bad;
  }
  if (meta.range && (kind === "int" || kind === "double")) {
    for (const item of items) {
      const bad = rangeProblem(meta.range, item);
      if (bad) return bad;
    }
  }
  if (meta.choices) {
    const check = isArrayType(meta.type) ? VALIDATORS.subset_of : VALIDATORS.one_of;
    const bad = check(value, meta.choices);
    if (bad) return bad;
  }
  for (const [rule, argument] of meta.validators || []) {
    const check = VALIDATORS[rule];
    const bad = check ? check(value, argument) : null;
    if (bad) return bad;
  }
  return null;
}
