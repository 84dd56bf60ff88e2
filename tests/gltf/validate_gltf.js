// Runs the Khronos glTF Validator (npm package gltf-validator) on each FILE and prints one line of
// JSON per file: its errors, warnings, infos and hints, and every issue's code and pointer.
// Usage: node validate_gltf.js VALIDATOR_DIR FILE...   (VALIDATOR_DIR holds node_modules/)
// Exits 1 if any file has an error or a warning, 2 on bad usage, 77 (skipped) without the package.
const fs = require("fs");
const path = require("path");

const [validatorDir, ...files] = process.argv.slice(2);
if (!validatorDir || files.length === 0) {
  console.error("usage: node validate_gltf.js VALIDATOR_DIR FILE...");
  process.exit(2);
}
let validator;
try {
  validator = require(path.join(path.resolve(validatorDir), "node_modules", "gltf-validator"));
} catch (e) {
  console.log(`gltf-validator not installed in ${validatorDir}/node_modules: skipped`);
  process.exit(77);
}

(async () => {
  let failed = false;
  for (const file of files) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
      uri: path.basename(file),
      maxIssues: 100,
    });
    const issues = report.issues;
    const line = {
      file: path.basename(file),
      validator: report.validatorVersion,
      errors: issues.numErrors,
      warnings: issues.numWarnings,
      infos: issues.numInfos,
      hints: issues.numHints,
      issues: issues.messages.map((m) => `${m.code} ${m.pointer || ""} ${m.message}`.trim()),
    };
    console.log("GLTF_VALIDATOR " + JSON.stringify(line));
    if (issues.numErrors > 0 || issues.numWarnings > 0) failed = true;
  }
  process.exit(failed ? 1 : 0);
})().catch((e) => {
  console.error(`gltf-validator failed: ${e}`);
  process.exit(1);
});
