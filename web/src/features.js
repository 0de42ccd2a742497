// The property table of a GLB that Insula writes (EXT_structural_metadata, docs/formats.md "Parts
// as features"): a row per part, read here so a click on a merged mesh (one mesh for the whole
// scene) can name the part and its building. Columns: STRING (UTF-8 values with UINT32 offsets),
// ENUM (UINT8 or UINT16 codes), SCALAR FLOAT64 and BOOLEAN (a bit per row); uncompressed views.

function glbChunks(bytes) {
  const view = new DataView(bytes);
  const jsonLength = view.getUint32(12, true);
  const json = JSON.parse(new TextDecoder().decode(new Uint8Array(bytes, 20, jsonLength)));
  const binaryStart = 20 + jsonLength + 8;
  return { json, binaryStart };
}

// { rows, columns: { property: [value per row] } }, or null when the GLB has no table.
export function readPropertyTable(bytes) {
  const { json, binaryStart } = glbChunks(bytes);
  const metadata = json.extensions && json.extensions.EXT_structural_metadata;
  if (!metadata || !metadata.propertyTables || metadata.propertyTables.length === 0) return null;
  const table = metadata.propertyTables[0];
  const klass = metadata.schema.classes[table.class].properties;
  const enums = metadata.schema.enums || {};
  const viewBytes = (index) => {
    const v = json.bufferViews[index];
    return new Uint8Array(bytes, binaryStart + (v.byteOffset || 0), v.byteLength);
  };
  const decoder = new TextDecoder();
  const columns = {};
  for (const [id, property] of Object.entries(table.properties)) {
    const spec = klass[id];
    const values = viewBytes(property.values);
    const data = new DataView(values.buffer, values.byteOffset, values.byteLength);
    const rows = [];
    for (let row = 0; row < table.count; ++row) {
      if (spec.type === 'STRING') {
        const offsets = viewBytes(property.stringOffsets);
        const at = new DataView(offsets.buffer, offsets.byteOffset, offsets.byteLength);
        rows.push(decoder.decode(values.subarray(at.getUint32(4 * row, true), at.getUint32(4 * row + 4, true))));
      } else if (spec.type === 'ENUM') {
        const e = enums[spec.enumType];
        const code = e.valueType === 'UINT16' ? data.getUint16(2 * row, true) : data.getUint8(row);
        const name = (e.values.find((v) => v.value === code) || {}).name;
        rows.push(name === spec.noData ? undefined : name);
      } else if (spec.type === 'BOOLEAN') {
        rows.push(((values[row >> 3] >> (row & 7)) & 1) === 1);
      } else {
        rows.push(data.getFloat64(8 * row, true));
      }
    }
    columns[spec.name || id] = rows;
  }
  return { rows: table.count, columns };
}

// The attributes of part `row` of the table, without the ones it lacks.
export function featureRow(table, row) {
  const out = {};
  for (const [name, values] of Object.entries(table.columns)) {
    if (values[row] !== undefined && values[row] !== '') out[name] = values[row];
  }
  return out;
}
