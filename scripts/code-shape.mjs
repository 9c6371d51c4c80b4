// The code's shape, checked (ARCHITECTURE.md, "Size limits"): no function over 120 lines in src/
// or www/ and no JavaScript closure (a function with functions inside it) over 300 lines, unless a
// comment `// long: <reason>` stands directly above it; no JavaScript file in www/ over 600 lines.
//
//   node scripts/code-shape.mjs           report, exit 1 on any violation
//   node scripts/code-shape.mjs --list N  also list every function over N lines (a survey)
//
// JavaScript is parsed with acorn (a dev dependency). Rust functions are
// found by a small scanner: an `fn` item's body runs from its first `{` to the matching `}`,
// skipping braces inside strings, chars and comments. Vendored and generated files are skipped.
import { readFileSync, readdirSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { parse } from 'acorn';

const ROOT = join(fileURLToPath(new URL('.', import.meta.url)), '..');
const FUNCTION_LINES = 120;
const CLOSURE_LINES = 300;
const JS_FILE_LINES = 600;
const SKIP = ['www/pkg', 'www/vendor', 'www/node_modules', 'www/lab.bundle.js'];

/** Every file under `dir` whose name ends in one of `exts`, as repository-relative paths. */
export function walk(dir, exts) {
  const out = [];
  for (const name of readdirSync(join(ROOT, dir))) {
    const rel = join(dir, name);
    if (SKIP.some((s) => rel === s || rel.startsWith(`${s}/`))) continue;
    const st = statSync(join(ROOT, rel));
    if (st.isDirectory()) out.push(...walk(rel, exts));
    else if (exts.some((e) => name.endsWith(e))) out.push(rel);
  }
  return out.sort();
}

/** Whether the line above `line` (0-based) is a `// long: reason` comment with a reason. */
function excused(lines, line) {
  for (let i = line - 1; i >= 0 && i >= line - 3; i--) {
    const t = lines[i].trim();
    if (/^\/\/\s*long:\s*\S/.test(t)) return true;
    if (t !== '' && !t.startsWith('//') && !t.startsWith('#[') && !t.startsWith('*') && !t.startsWith('/**')) break;
  }
  return false;
}

/**
 * The functions of a JavaScript source: name, first line (0-based), length in lines, and
 * whether another function is nested in it (a closure in the sense of this check).
 */
export function jsFunctions(text) {
  const ast = parse(text, { ecmaVersion: 'latest', sourceType: 'module', locations: true, allowHashBang: true });
  const out = [];
  const FN = new Set(['FunctionDeclaration', 'FunctionExpression', 'ArrowFunctionExpression']);
  // The statement that holds a function (for `const f = () => …` the comment sits above it).
  const HOLDERS = new Set([
    'VariableDeclaration',
    'ExportNamedDeclaration',
    'ExportDefaultDeclaration',
    'Property',
    'MethodDefinition',
    'PropertyDefinition',
    'ExpressionStatement',
    'AssignmentExpression',
    'VariableDeclarator',
  ]);
  const visit = (node, parents, stack) => {
    if (!node || typeof node.type !== 'string') return;
    let inner = stack;
    if (FN.has(node.type)) {
      let anchorLine = node.loc.start.line;
      let name = node.id?.name;
      for (let k = parents.length - 1; k >= 0 && HOLDERS.has(parents[k].type); k--) {
        const p = parents[k];
        anchorLine = Math.min(anchorLine, p.loc.start.line);
        if (!name && p.type === 'VariableDeclarator' && p.id.type === 'Identifier') name = p.id.name;
        if (
          !name &&
          (p.type === 'Property' || p.type === 'MethodDefinition' || p.type === 'PropertyDefinition') &&
          p.key?.type === 'Identifier'
        )
          name = p.key.name;
      }
      const entry = {
        name: name ?? '(anonymous)',
        line: anchorLine - 1,
        lines: node.loc.end.line - node.loc.start.line + 1,
        closure: false,
      };
      for (const outer of stack) outer.closure = true;
      out.push(entry);
      inner = [...stack, entry];
    }
    const next = [...parents, node];
    for (const key of Object.keys(node)) {
      if (key === 'loc') continue;
      const v = node[key];
      if (Array.isArray(v)) for (const c of v) visit(c, next, inner);
      else if (v && typeof v.type === 'string') visit(v, next, inner);
    }
  };
  visit(ast, [], []);
  return out;
}

/** The `fn` items of a Rust source: name, first line (0-based) and length in lines. */
export function rustFunctions(text) {
  const out = [];
  const n = text.length;
  // Mask strings, chars and comments so braces inside them do not count.
  const masked = text.split('');
  let i = 0;
  while (i < n) {
    const c = text[i];
    const d = text[i + 1];
    if (c === '/' && d === '/') {
      while (i < n && text[i] !== '\n') masked[i++] = ' ';
    } else if (c === '/' && d === '*') {
      let depth = 0;
      do {
        if (text[i] === '/' && text[i + 1] === '*') {
          depth++;
          masked[i] = masked[i + 1] = ' ';
          i += 2;
        } else if (text[i] === '*' && text[i + 1] === '/') {
          depth--;
          masked[i] = masked[i + 1] = ' ';
          i += 2;
        } else {
          if (text[i] !== '\n') masked[i] = ' ';
          i++;
        }
      } while (i < n && depth > 0);
    } else if (
      c === 'r' &&
      (d === '"' || (d === '#' && /^r#+"/.test(text.slice(i, i + 10)))) &&
      !/[A-Za-z0-9_]/.test(text[i - 1] ?? '')
    ) {
      const hashes = /^r(#*)"/.exec(text.slice(i, i + 10))[1];
      const close = `"${hashes}`;
      const j = text.indexOf(close, i + 2 + hashes.length);
      const stop = j < 0 ? n : j + close.length;
      for (; i < stop; i++) if (text[i] !== '\n') masked[i] = ' ';
    } else if (c === '"') {
      masked[i++] = ' ';
      while (i < n && text[i] !== '"') {
        if (text[i] === '\\') {
          masked[i++] = ' ';
        }
        if (i < n && text[i] !== '\n') masked[i] = ' ';
        i++;
      }
      if (i < n) masked[i++] = ' ';
    } else if (c === "'" && /^'(\\.[^']*|[^\\'])'/.test(text.slice(i, i + 12))) {
      const m = /^'(\\.[^']*|[^\\'])'/.exec(text.slice(i, i + 12))[0];
      for (let k = 0; k < m.length; k++) masked[i + k] = ' ';
      i += m.length;
    } else i++;
  }
  const src = masked.join('');
  const lineStarts = [0];
  for (let k = 0; k < n; k++) if (text[k] === '\n') lineStarts.push(k + 1);
  const lineOf = (pos) => {
    let lo = 0,
      hi = lineStarts.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (lineStarts[mid] <= pos) lo = mid;
      else hi = mid - 1;
    }
    return lo;
  };
  const re = /\bfn\s+([A-Za-z_][A-Za-z0-9_]*)/g;
  for (let m = re.exec(src); m; m = re.exec(src)) {
    // The body: the first `{` after the signature at paren depth 0, unless a `;` comes first.
    let k = m.index + m[0].length;
    let paren = 0;
    let open = -1;
    for (; k < n; k++) {
      const ch = src[k];
      if (ch === '(' || ch === '<' || ch === '[') paren++;
      else if (ch === ')' || ch === ']' || (ch === '>' && src[k - 1] !== '-' && src[k - 1] !== '=')) paren--;
      else if (ch === ';' && paren <= 0) break;
      else if (ch === '{' && paren <= 0) {
        open = k;
        break;
      }
    }
    if (open < 0) continue;
    let depth = 0;
    let close = open;
    for (; close < n; close++) {
      if (src[close] === '{') depth++;
      else if (src[close] === '}' && --depth === 0) break;
    }
    out.push({ name: m[1], line: lineOf(m.index), lines: lineOf(close) - lineOf(m.index) + 1 });
  }
  return out;
}

function main() {
  const listAt = process.argv.includes('--list') ? Number(process.argv[process.argv.indexOf('--list') + 1]) : null;
  const problems = [];
  const survey = [];
  for (const file of walk('www', ['.js', '.mjs'])) {
    const text = readFileSync(join(ROOT, file), 'utf8');
    const lines = text.split('\n');
    const count = text.endsWith('\n') ? lines.length - 1 : lines.length;
    if (count > JS_FILE_LINES) problems.push(`${file}: ${count} lines (files in www/ stay under ${JS_FILE_LINES})`);
    for (const f of jsFunctions(text)) {
      if (listAt !== null && f.lines > listAt)
        survey.push([f.lines, `${file}:${f.line + 1} ${f.name}${f.closure ? ' (closure)' : ''}`]);
      if (excused(lines, f.line)) continue;
      if (f.closure && f.lines > CLOSURE_LINES)
        problems.push(`${file}:${f.line + 1}: closure ${f.name} is ${f.lines} lines (at most ${CLOSURE_LINES})`);
      else if (!f.closure && f.lines > FUNCTION_LINES)
        problems.push(`${file}:${f.line + 1}: function ${f.name} is ${f.lines} lines (at most ${FUNCTION_LINES})`);
    }
  }
  for (const file of walk('src', ['.rs'])) {
    const text = readFileSync(join(ROOT, file), 'utf8');
    const lines = text.split('\n');
    for (const f of rustFunctions(text)) {
      if (listAt !== null && f.lines > listAt) survey.push([f.lines, `${file}:${f.line + 1} fn ${f.name}`]);
      if (f.lines > FUNCTION_LINES && !excused(lines, f.line))
        problems.push(`${file}:${f.line + 1}: fn ${f.name} is ${f.lines} lines (at most ${FUNCTION_LINES})`);
    }
  }
  if (listAt !== null)
    for (const [, s] of survey.sort((a, b) => b[0] - a[0]))
      console.log(`${s} — ${survey.find((x) => x[1] === s)[0]} lines`);
  if (problems.length) {
    console.error(
      `code-shape: ${problems.length} over the limits (a \`// long: <reason>\` comment directly above excuses a function):`,
    );
    for (const p of problems) console.error(`  ${p}`);
    process.exit(1);
  }
  console.log('code-shape: every function, closure and www/ file within the limits');
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) main();
