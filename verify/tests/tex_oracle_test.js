// The TeX oracle: every row of math of the documents given, read by our reader (tex_oracle_dump)
// and by KaTeX's parser (Debian's libjs-katex), must have one structure: the same fractions,
// scripts, roots, \left...\right, matrices and symbols, in the same order, none dropped. KaTeX
// expands the document's macros itself, from their definitions as the source prints them. A row
// our reader refuses while KaTeX reads it is a failure too; one KaTeX refuses is reported and
// counts as a failure unless our reader refuses it as well.
//
//   node tex_oracle_test.js KATEX_JS DUMP_BINARY FILE.tex...
//   node tex_oracle_test.js --drop-a-token KATEX_JS DUMP_BINARY FILE.tex...
// The second is the oracle's own test: our tree of every row loses one symbol, as a reader that
// dropped a token would, and every row compared must then fail (exit 0 when every one does).

'use strict';
const { execFileSync } = require('child_process');

const args = process.argv.slice(2);
const selfTest = args[0] === '--drop-a-token';
if (selfTest) args.shift();
const [katexPath, dump, ...files] = args;
const katex = require(katexPath);

// What the documents use that is not math: KaTeX drops them by the same rules as our reader.
const preamble = {
  '\\label': { tokens: [], numArgs: 1 },
  '\\svgobble': { tokens: [], numArgs: 1 },
  '\\vspace': '\\@ifstar\\svgobble\\svgobble',
  '\\nonumber': '',
  '\\notag': '',
};

// KaTeX's definitions of a macro: the source's own where KaTeX reads it, else an equivalent.
function definition(d) {
  if (d.command === '\\DeclareMathOperator') return `\\def${d.name}{${d.body}}`;
  if (d.default !== null) {
    // \newcommand{\x}[n][default]{body}: \@ifnextchar[ as LaTeX does it.
    const rest = Array.from({ length: d.arguments - 1 }, (_, k) => `#${k + 2}`).join('');
    const opt = d.name + 'svopt';
    return `\\def${d.name}{\\@ifnextchar[{${opt}}{${opt}[${d.default}]}}\\def${opt}[#1]${rest}{${d.body}}`;
  }
  if (d.command === '\\renewcommand' || d.command === '\\providecommand') return d.source.replace(d.command, '\\newcommand');
  return d.source;
}

const same = { '\\le': '\\leq', '\\ge': '\\geq', '\\ne': '\\neq', '\\dots': '\\ldots', '\\@cdots': '\\cdots', '\\lbrace': '\\{',
               '\\rbrace': '\\}', '\\to': '\\rightarrow', '\\vert': '|', '\\|': '\\Vert', '\\implies': '\\Longrightarrow' };
const canon = (t) => (t in same ? same[t] : t);

function joined(items) { return items.length === 1 ? items[0] : `[${items.join(' ')}]`; }
function list(nodes) {
  const out = [];
  for (const n of nodes) item(n, out);
  return joined(out);
}
const arg = (n) => (n ? list([n]) : '[]');

function item(n, out) {
  switch (n.type) {
    case 'mathord': case 'textord': case 'atom': out.push(canon(n.text)); break;
    case 'op':
      if (n.name) out.push(n.name);
      else out.push(`(op ${list(n.body)})`);
      break;
    case 'ordgroup': if (n.body.length) out.push(list(n.body)); break;
    case 'styling': case 'sizing': case 'mclass': case 'tag': for (const c of n.body) item(c, out); break;
    case 'spacing': case 'kern': case 'internal': break;
    case 'genfrac': {
      const kind = n.hasBarLine ? 'frac' : (n.leftDelim === '(' ? 'binom' : 'atop');
      out.push(`(${kind} ${arg(n.numer)} ${arg(n.denom)})`);
      break;
    }
    case 'sqrt': out.push(`(sqrt ${arg(n.body)}${n.index ? ' ' + arg(n.index) : ''})`); break;
    case 'supsub': {
      const base = arg(n.base);
      if (n.sup && n.sub) out.push(`(supsub ${base} ${arg(n.sup)} ${arg(n.sub)})`);
      else if (n.sup) out.push(`(sup ${base} ${arg(n.sup)})`);
      else out.push(`(sub ${base} ${arg(n.sub)})`);
      break;
    }
    case 'leftright': out.push(`(left ${canon(n.left)} ${canon(n.right)} ${list(n.body)})`); break;
    case 'middle': out.push(canon(n.delim)); break;
    case 'delimsizing': out.push(canon(n.delim)); break;
    case 'array': {
      const rows = n.body.map((row) => `(row${row.map((c) => ' ' + list([c])).join('')})`);
      out.push(`(array${rows.map((r) => ' ' + r).join('')})`);
      break;
    }
    case 'font': out.push(`(font ${n.font} ${arg(n.body)})`); break;
    case 'operatorname': out.push(`(operatorname ${list(n.body)})`); break;
    case 'accent': out.push(`(accent ${n.label} ${arg(n.base)})`); break;
    case 'overline': case 'underline': out.push(`(accent \\${n.type} ${arg(n.body)})`); break;
    case 'text': out.push(`(text ${n.body.filter((c) => c.type !== 'spacing').map((c) => c.text).join('')})`); break;
    default: out.push(`(?${n.type})`);
  }
}

// An align row's cells, one list: our reader reads the alignment points by their rule.
function rowForm(tree, aligned) {
  if (!aligned) return list(tree);
  const array = tree.find((n) => n.type === 'array');
  const cells = [];
  // A cell is KaTeX's styling around an ordgroup: its symbols, not a group of them.
  const cellItems = (c) => {
    if (c.type === 'styling') for (const x of c.body) cellItems(x);
    else if (c.type === 'ordgroup') for (const x of c.body) item(x, cells);
    else item(c, cells);
  };
  for (const row of array.body) for (const c of row) cellItems(c);
  return joined(cells);
}

// Our form without its last symbol: "[a b c]" -> "[a b]", "x" -> "[]".
function dropped(form) {
  const m = /^(.*[\s\[(])([^\s\[\]()]+)([\s\])].*)$/.exec(form);
  if (!m) return '[]';
  return m[1].replace(/\s$/, '') + m[3];
}

const rows = execFileSync(dump, files, { encoding: 'utf8', maxBuffer: 64 << 20 }).split('\n').filter((l) => l.trim());
let failures = 0, compared = 0;
for (const line of rows) {
  const r = JSON.parse(line);
  const where = `${r.file}:${r.line}`;
  if (r.document_refused) {
    console.log(`FAIL ${r.file}: our reader refuses the document: ${r.document_refused}`);
    ++failures;
    continue;
  }
  const definitions = r.definitions.map(definition).join('');
  const open = r.environment.startsWith('eqnarray') ? '\\begin{array}{rcl}' : '\\begin{aligned}';
  const close = r.environment.startsWith('eqnarray') ? '\\end{array}' : '\\end{aligned}';
  const input = definitions + (r.aligned ? open + r.tex + close : r.tex);
  let theirs;
  try {
    theirs = rowForm(katex.__parse(input, { displayMode: true, throwOnError: true, strict: 'ignore', macros: Object.assign({}, preamble) }), r.aligned);
  } catch (e) {
    if (r.refused) {
      console.log(`ok   ${where}: both refuse (ours: ${r.refused}; KaTeX: ${e.message.split('\n')[0]})`);
    } else {
      console.log(`FAIL ${where}: KaTeX refuses what our reader reads: ${e.message.split('\n')[0]}\n     ${r.tex}`);
      ++failures;
    }
    continue;
  }
  if (selfTest && (r.refused || r.ours === '[]')) continue;  // nothing to drop
  ++compared;
  if (selfTest) r.ours = dropped(r.ours);
  if (r.refused) {
    console.log(`FAIL ${where}: our reader refuses what KaTeX reads: ${r.refused}\n     ${r.tex}`);
    ++failures;
  } else if (theirs !== r.ours) {
    console.log(`FAIL ${where}: the trees differ\n     TeX:   ${r.tex}\n     ours:  ${r.ours}\n     KaTeX: ${theirs}`);
    ++failures;
  }
}
console.log(`${rows.length} rows of ${files.length} document(s): ${compared} compared, ${failures} failed`);
if (selfTest) {
  const caught = failures === compared && compared > 0;
  console.log(caught ? 'the oracle caught every dropped token' : `the oracle missed ${compared - failures} dropped token(s)`);
  process.exit(caught ? 0 : 1);
}
process.exit(failures ? 1 : 0);
