// Editors for the graph's variables, checks and settings. Their fields come from the graph format's schema
// (GET /api/forms); the page only turns text into JSON values: every change goes to /api/check, and each
// problem is shown beside the variable, check or setting it names.
import React, { useEffect, useState } from "react";
import PrimPicker from "./PrimPicker.jsx";

/** Problems about a part of the document: by their JSON path, or the variable they name. */
export function problemsAt(problems, section, key) {
  return problems.filter((problem) => {
    const path = problem.path || [];
    if (path[0] === section && (key === undefined || path[1] === key)) return true;
    if (section === "variables" && problem.kind === "variable") return key === undefined || problem.attribute === key;
    const named = (problem.message || "").match(/^settings[./](\w+)/);
    return section === "settings" && named && (key === undefined || named[1] === key);
  });
}

function Problems({ list, testid }) {
  return list.map((problem, index) => <div key={index} className="gf-problem" data-problem={testid}>{problem.message}</div>);
}

function textOf(value) {
  if (value === undefined) return "";
  return typeof value === "string" ? value : JSON.stringify(value);
}

/** Text typed into a field as the JSON value it stands for; text that is not JSON stays a string (the check says why). */
export function parsed(text, schema = {}) {
  if (text.trim() === "") return undefined;
  if (schema.type === "string" || (schema.enum && schema.enum.every((item) => typeof item === "string"))) return text;
  try {
    return JSON.parse(text);
  } catch {
    return text;
  }
}

function Field({ name, schema, value, onChange, testid, list }) {
  const [draft, setDraft] = useState(textOf(value));
  useEffect(() => setDraft(textOf(value)), [value]);
  if (schema.enum) {
    return (
      <select data-field={testid} value={value ?? ""} onChange={(event) => onChange(event.target.value === "" ? undefined : event.target.value)}>
        <option value="">(default)</option>
        {schema.enum.map((item) => <option key={item} value={item}>{item}</option>)}
      </select>
    );
  }
  const commit = () => draft !== textOf(value) && onChange(parsed(draft, schema));
  return <input type="text" data-field={testid} value={draft} title={schema.description || ""} list={list}
                placeholder={schema.type === "number" || schema.type === "integer" ? "a number" : ""}
                onChange={(event) => setDraft(event.target.value)} onBlur={commit}
                onKeyDown={(event) => event.key === "Enter" && commit()} />;
}

function withKey(object, key, value) {
  const next = { ...object };
  if (value === undefined) delete next[key];
  else next[key] = value;
  return next;
}

export function VariablesEditor({ data, types, problems, edit }) {
  const variables = data.variables || [];
  const change = (index, key, value) => edit((doc) => {
    doc.variables[index] = withKey(doc.variables[index], key, value);
    return doc;
  });
  return (
    <section className="gf-doc-editor" data-testid="variables-editor">
      <datalist id="gf-types">{types.map((type) => <option key={type} value={type} />)}</datalist>
      {variables.map((variable, index) => (
        <div key={index} className="gf-doc-item" data-variable={index}>
          <label>name <Field name="name" schema={{ type: "string" }} value={variable.name} testid="variable-name"
                             onChange={(value) => change(index, "name", value ?? "")} /></label>
          <label>type <input list="gf-types" data-field="variable-type" defaultValue={variable.type} key={variable.type}
                             onBlur={(event) => event.target.value !== variable.type && change(index, "type", event.target.value)}
                             onKeyDown={(event) => event.key === "Enter" && change(index, "type", event.target.value)} /></label>
          <label>default <Field name="default" schema={{}} value={variable.default} testid="variable-default"
                                onChange={(value) => change(index, "default", value)} /></label>
          <label>description <Field name="description" schema={{ type: "string" }} value={variable.description}
                                    testid="variable-description" onChange={(value) => change(index, "description", value)} /></label>
          <button type="button" data-action="delete-variable" onClick={() => edit((doc) => {
            doc.variables.splice(index, 1);
            if (!doc.variables.length) delete doc.variables;
            return doc;
          })}>delete</button>
          <Problems list={[...problemsAt(problems, "variables", index), ...problemsAt(problems, "variables", variable.name)]}
                    testid={`variable-${index}`} />
        </div>
      ))}
      <button type="button" data-action="add-variable" onClick={() => edit((doc) => {
        const taken = new Set((doc.variables || []).map((variable) => variable.name));
        let index = 1;
        while (taken.has(`variable${index}`)) index += 1;
        doc.variables = [...(doc.variables || []), { name: `variable${index}`, type: "double", default: 0.0 }];
        return doc;
      })}>add a variable</button>
    </section>
  );
}

function CheckFields({ check, index, forms, stagePrims, edit }) {
  const rule = forms.checks[check.check];
  if (!rule) return null;
  const change = (key, value) => edit((doc) => {
    doc.checks[index] = withKey(doc.checks[index], key, value);
    return doc;
  });
  return Object.entries(rule.properties).filter(([key]) => key !== "check").map(([key, schema]) => {
    const required = (rule.required || []).includes(key);
    const kind = forms.checkPrimKinds[key];
    return (
      <label key={key} title={schema === true ? "" : schema.description || ""}>
        {key}{required ? " *" : ""}{" "}
        {kind
          ? <PrimPicker name={`check-${index}-${key}`} value={check[key]} kind={kind} stagePrims={stagePrims}
                        many={key === "prims"} onChange={(value) => change(key, value === "" || (Array.isArray(value) && !value.length) ? undefined : value)} />
          : <Field name={key} schema={schema === true ? { type: "string" } : schema} value={check[key]} testid={`check-${key}`}
                   onChange={(value) => change(key, value)} />}
      </label>
    );
  });
}

export function ChecksEditor({ data, forms, problems, stagePrims, edit }) {
  const checks = data.checks || [];
  const [kind, setKind] = useState(Object.keys(forms.checks)[0]);
  return (
    <section className="gf-doc-editor" data-testid="checks-editor">
      {checks.map((check, index) => (
        <div key={index} className="gf-doc-item" data-check-item={index} data-check-kind={check.check}>
          <b>{index + 1}. {check.check}</b>
          <button type="button" data-action="delete-check" onClick={() => edit((doc) => {
            doc.checks.splice(index, 1);
            if (!doc.checks.length) delete doc.checks;
            return doc;
          })}>delete</button>
          <CheckFields check={check} index={index} forms={forms} stagePrims={stagePrims} edit={edit} />
          <Problems list={problemsAt(problems, "checks", index)} testid={`check-${index}`} />
        </div>
      ))}
      <select data-field="new-check" value={kind} onChange={(event) => setKind(event.target.value)}>
        {Object.keys(forms.checks).map((name) => <option key={name} value={name}>{name}</option>)}
      </select>
      <button type="button" data-action="add-check" onClick={() => edit((doc) => {
        doc.checks = [...(doc.checks || []), { check: kind }];
        return doc;
      })}>add a check</button>
      <p className="gf-description">docs/checks.md says what each check measures; * marks the fields it needs.</p>
    </section>
  );
}

export function SettingsEditor({ data, forms, problems, stages, edit }) {
  const settings = data.settings || {};
  const change = (key, value) => edit((doc) => {
    doc.settings = withKey(doc.settings || {}, key, value);
    if (!Object.keys(doc.settings).length) delete doc.settings;
    return doc;
  });
  const seed = data.scenario ? data.scenario.seed : undefined;
  const step = settings.timeStep;
  return (
    <section className="gf-doc-editor" data-testid="settings-editor">
      <datalist id="gf-stages">{(stages || []).map((stage) => <option key={stage} value={stage} />)}</datalist>
      {Object.entries(forms.settings).filter(([key]) => key !== "missingAssets").map(([key, schema]) => (
        <div key={key} className="gf-doc-item" data-setting={key}>
          <label title={schema.description || ""}>{key} <Field name={key} schema={schema} value={settings[key]} testid={`setting-${key}`}
                                                               list={key === "stage" ? "gf-stages" : undefined}
                                                               onChange={(value) => change(key, value)} /></label>
          {key === "timeStep" && typeof step === "number" && step > 0 && <small> physics rate {(1 / step).toFixed(1)} Hz</small>}
          <Problems list={problemsAt(problems, "settings", key)} testid={`setting-${key}`} />
        </div>
      ))}
      <div className="gf-doc-item" data-setting="seed">
        <label title={forms.seed.description}>seed <Field name="seed" schema={forms.seed} value={seed} testid="setting-seed"
          onChange={(value) => edit((doc) => {
            doc.scenario = withKey(doc.scenario || {}, "seed", value);
            if (!Object.keys(doc.scenario).length) delete doc.scenario;
            return doc;
          })} /></label>
        <Problems list={problemsAt(problems, "scenario")} testid="setting-seed" />
      </div>
    </section>
  );
}
