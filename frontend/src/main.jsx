import React from "react";
import { createRoot } from "react-dom/client";
import "@xyflow/react/dist/style.css";
import "./style.css";
import App from "./App.jsx";
import { readRun } from "./data.js";

const run = readRun();
document.title = `${run.header.graph} — graphflow run report`;
createRoot(document.getElementById("root")).render(<App run={run} />);
