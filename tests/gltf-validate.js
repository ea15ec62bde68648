#!/usr/bin/env node
// gltf-validate.js -- run Khronos' glTF-Validator (npm gltf-validator,
// a devDependency in package.json: `make deps` installs it in node_modules) on .glb/.gltf
// files.  Prints one summary line per file,
//   FILE: 0 errors, 0 warnings, 2 infos, 0 hints
// followed by every error and warning ("  ERROR CODE pointer: message").
// Exit 0 if no file has an error or a warning, 1 if one has, 2 if the
// validator is not installed or a file cannot be read.
'use strict';
const fs = require('fs');
const path = require('path');

const here = __dirname;
const where = process.env.STOPMO_NODE_MODULES || path.join(here, '..', 'node_modules');
let validator;
try {
    validator = require(path.join(where, 'gltf-validator'));
} catch (e) {
    console.error(`gltf-validate: gltf-validator is not installed in ${where} (run make deps)`);
    process.exit(2);
}

const severity = ['ERROR', 'WARNING', 'INFO', 'HINT'];

async function check(file) {
    const bytes = new Uint8Array(fs.readFileSync(file));
    const report = await validator.validateBytes(bytes, {
        uri: path.basename(file),
        maxIssues: 0,
        externalResourceFunction: (uri) => new Promise((resolve, reject) => {
            const p = path.resolve(path.dirname(file), decodeURIComponent(uri));
            fs.readFile(p, (err, data) => err ? reject(err.toString()) : resolve(new Uint8Array(data)));
        }),
    });
    const is = report.issues;
    console.log(`${file}: ${is.numErrors} errors, ${is.numWarnings} warnings, ${is.numInfos} infos, ${is.numHints} hints`);
    for (const m of is.messages)
        if (m.severity <= 1 || process.env.GLTF_VALIDATE_ALL)
            console.log(`  ${severity[m.severity]} ${m.code} ${m.pointer || ''}: ${m.message}`);
    return is.numErrors + is.numWarnings === 0;
}

(async () => {
    const files = process.argv.slice(2);
    if (!files.length) {
        console.error('usage: gltf-validate.js FILE.glb|FILE.gltf...');
        process.exit(2);
    }
    let ok = true;
    for (const f of files) {
        try {
            if (!(await check(f))) ok = false;
        } catch (e) {
            console.error(`gltf-validate: ${f}: ${e}`);
            process.exit(2);
        }
    }
    process.exit(ok ? 0 : 1);
})();
