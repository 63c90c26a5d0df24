// Bundles the viewer for `wpg view` (run by CMake, analysis/viewer/CMakeLists.txt):
//   node build.mjs OUT_DIR NODE_MODULES_DIR
// writes OUT_DIR/wpg_viewer.js (src/main.js with three.js and urdf-loader, minified, one
// script that the page holds inline) and OUT_DIR/page.html (the template). The licences of the
// bundled packages are kept at the top of the script. A script that holds "</script" could not
// be inlined in a page: that is an error here, not a broken page later.
import { copyFileSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const [outDir, modulesArgument] = process.argv.slice(2);
if (!outDir || !modulesArgument) {
  console.error('usage: node build.mjs OUT_DIR NODE_MODULES_DIR');
  process.exit(2);
}
const modules = resolve(modulesArgument);
// esbuild from the build tree's node_modules (npm ci there), not from beside this file.
const { build } = (await import(pathToFileURL(join(modules, 'esbuild', 'lib', 'main.js')).href)).default;

function licence(name, file) {
  const text = readFileSync(join(modules, name, file), 'utf8').replaceAll('*/', '* /');
  const version = JSON.parse(readFileSync(join(modules, name, 'package.json'), 'utf8')).version;
  return `/*! ${name} ${version}\n${text.trim()}\n*/`;
}
const urdfLoader = JSON.parse(readFileSync(join(modules, 'urdf-loader', 'package.json'), 'utf8'));
const banner = [
  '/*! wpg view: the page of a run or a study (analysis/viewer). Bundled packages and their licences follow. */',
  licence('three', 'LICENSE'),
  // urdf-loader ships no licence file: its package.json names the licence and the author.
  `/*! urdf-loader ${urdfLoader.version}: ${urdfLoader.license} licence, ${urdfLoader.author || 'Garrett Johnson'}, ${urdfLoader.repository?.url || urdfLoader.homepage || ''} */`,
].join('\n');

const outfile = join(outDir, 'wpg_viewer.js');
await build({
  entryPoints: [join(here, 'src', 'main.js')],
  bundle: true,
  minify: true,
  format: 'iife',
  target: 'es2020',
  legalComments: 'none',
  nodePaths: [modules],
  banner: { js: banner },
  outfile,
  logLevel: 'warning',
});
const script = readFileSync(outfile, 'utf8');
if (/<\/script/i.test(script)) {
  console.error(`${outfile}: holds "</script": it cannot be inlined in the page`);
  process.exit(1);
}
copyFileSync(join(here, 'page.html'), join(outDir, 'page.html'));
writeFileSync(join(outDir, 'wpg_viewer.stamp'), `${script.length} bytes\n`);
