// Builds the report page into ONE self-contained HTML file (JS and CSS inlined) inside the Python
// package, so `pip install graphflow` needs no Node. graphflow.report fills in the run's data.
import { defineConfig } from "vite";
import react from "@vitejs/plugin-react";
import { viteSingleFile } from "vite-plugin-singlefile";
import { fileURLToPath } from "node:url";

const outDir = process.env.GRAPHFLOW_REPORT_OUT
  || fileURLToPath(new URL("../graphflow/report/bundle", import.meta.url));

export default defineConfig({
  plugins: [react(), viteSingleFile({ removeViteModuleLoader: true })],
  logLevel: "warn",
  build: {
    outDir,
    emptyOutDir: true,
    target: "es2020",
    reportCompressedSize: false,
    rollupOptions: { input: fileURLToPath(new URL("report.html", import.meta.url)) },
  },
});
