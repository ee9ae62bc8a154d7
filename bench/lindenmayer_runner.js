// The lindenmayer@1.5.4 side of bench/lsystem_vs_lindenmayer.sh: the same systems as
// bench_lsystem.cpp, written the way that library's documentation writes them.
// usage: node lindenmayer_runner.js NODE_MODULES CASE N [REPEAT]
//   -> "length L" "modules_total T" "seconds S" "cpu_seconds C" (means over REPEAT runs)
const path = require('path');
const LSystem = require(path.join(process.argv[2], 'lindenmayer'));
const kase = process.argv[3];
const n = parseInt(process.argv[4], 10);

function system(kase) {
  switch (kase) {
    case 'a':  // ABOP fig. 1.24f, plain strings
      return new LSystem({axiom: 'X', productions: {X: 'F-[[X]+X]+F[+FX]-X', F: 'FF'}});
    case 'b': {  // parametric binary tree A(s) -> F(s)[+A(s/1.456)][-A(s/1.456)]
      const sym = (s) => ({symbol: s});
      return new LSystem({
        axiom: [{symbol: 'A', params: [1]}],
        productions: {
          A: ({part}) => {
            const s = part.params[0], t = s / 1.456;
            return [{symbol: 'F', params: [s]}, sym('['), sym('+'), {symbol: 'A', params: [t]},
                    sym(']'), sym('['), sym('-'), {symbol: 'A', params: [t]}, sym(']')];
          },
        },
      });
    }
    case 's':  // ABOP fig. 1.27, stochastic: the library's weighted successors
      return new LSystem({
        axiom: 'F',
        productions: {
          F: {successors: [{weight: 0.33, successor: 'F[+F]F[-F]F'},
                           {weight: 0.33, successor: 'F[+F]F'},
                           {weight: 0.34, successor: 'F[-F]F'}]},
        },
      });
    case 'p': {  // (b) with a stochastic choice: weighted successors that are functions
      const sym = (s) => ({symbol: s});
      return new LSystem({
        axiom: [{symbol: 'A', params: [1]}],
        productions: {
          A: {successors: [
            {weight: 0.5, successor: ({part}) => {
              const s = part.params[0], t = s / 1.456;
              return [{symbol: 'F', params: [s]}, sym('['), sym('+'), {symbol: 'A', params: [t]},
                      sym(']'), sym('['), sym('-'), {symbol: 'A', params: [t]}, sym(']')];
            }},
            {weight: 0.5, successor: ({part}) => {
              const s = part.params[0];
              return [{symbol: 'F', params: [s]}, sym('['), sym('-'),
                      {symbol: 'A', params: [s / 1.456]}, sym(']'), sym('+'),
                      {symbol: 'A', params: [s / 1.2]}];
            }},
          ]},
        },
      });
    }
    case 'c1':  // ABOP fig. 1.31a, context-sensitive, ignore + - F
      return new LSystem({
        axiom: 'F1F1F1',
        ignoredSymbols: '+-F',
        productions: {
          '0<0>0': '0', '0<0>1': '1[+F1F1]', '0<1>0': '1', '0<1>1': '1',
          '1<0>0': '0', '1<0>1': '1F1', '1<1>0': '1', '1<1>1': '0',
          '+': '-', '-': '+',
        },
      });
    case 'c2':  // internodes elongating above a node I, F ignored (see bench_lsystem.cpp)
      return new LSystem({
        axiom: 'IFA',
        ignoredSymbols: '+-F',
        productions: {A: 'IF[+A]IFA', 'I<F': 'FF'},
      });
  }
  throw new Error('unknown case ' + kase);
}

const repeat = Math.max(1, parseInt(process.argv[5] || '1', 10));
let ls, total = 0, seconds = 0, cpu = 0;
for (let r = 0; r < repeat; ++r) {
  ls = system(kase);
  total = 0;
  const c0 = process.cpuUsage();
  const t0 = process.hrtime.bigint();
  for (let i = 0; i < n; ++i) {
    ls.iterate(1);
    total += ls.axiom.length;
  }
  seconds += Number(process.hrtime.bigint() - t0) / 1e9;
  const c = process.cpuUsage(c0);  // user + system of the whole process (GC threads too)
  cpu += (c.user + c.system) / 1e6;
}
console.log('length ' + ls.axiom.length);
console.log('modules_total ' + total);
console.log('seconds ' + seconds / repeat);
console.log('cpu_seconds ' + cpu / repeat);
if (process.env.PRINT_STRING) console.log('string ' + ls.getString());
