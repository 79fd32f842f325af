import React from "react";
import { createRoot } from "react-dom/client";
import "@xyflow/react/dist/style.css";
import "./style.css";
import App from "./App.jsx";
import { readRun } from "./data.js";
import Studio from "./studio/Studio.jsx";
import { studioConfig } from "./studio/api.js";

// one bundle, two modes: a report embeds its run's data; the studio's server embeds its session instead
const studio = studioConfig();
if (studio) {
  document.title = "graphflow studio";
  createRoot(document.getElementById("root")).render(<Studio config={studio} />);
} else {
  const run = readRun();
  document.title = `${run.header.graph} — graphflow run report`;
  createRoot(document.getElementById("root")).render(<App run={run} />);
}
