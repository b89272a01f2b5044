// Independent KTX 2.0 check: parses a .ktx2 file with ktx-parse (not our reader) and prints a JSON summary
// that tests/io/ktx2_test.cpp compares with what our writer was given.
// Usage: node tests/js/check_ktx2.mjs FILE.ktx2
// Level data is reported as ktx-parse returns it: raw texels when supercompressionScheme is 0, the
// Zstandard frames otherwise (node has no zstd without another dependency, so only lengths are compared).
import { createHash } from 'node:crypto';
import { readFileSync } from 'node:fs';
import { read } from 'ktx-parse';

// Levels up to this size also get their bytes in hex, which the tests compare exactly.
const HEX_LIMIT = 1 << 16;

function text(value) {
  // ktx-parse hands back keys starting with "KTX" as strings (NUL already stripped), others as bytes.
  if (typeof value === 'string') return value;
  const nul = value.indexOf(0);
  return new TextDecoder().decode(nul < 0 ? value : value.subarray(0, nul));
}

function summarize(container) {
  const dfd = container.dataFormatDescriptor[0];
  return {
    vkFormat: container.vkFormat,
    typeSize: container.typeSize,
    pixelWidth: container.pixelWidth,
    pixelHeight: container.pixelHeight,
    pixelDepth: container.pixelDepth,
    layerCount: container.layerCount,
    faceCount: container.faceCount,
    levelCount: container.levelCount,
    supercompressionScheme: container.supercompressionScheme,
    dfd: {
      vendorId: dfd.vendorId,
      descriptorType: dfd.descriptorType,
      versionNumber: dfd.versionNumber,
      colorModel: dfd.colorModel,
      colorPrimaries: dfd.colorPrimaries,
      transferFunction: dfd.transferFunction,
      flags: dfd.flags,
      texelBlockDimension: dfd.texelBlockDimension,
      bytesPlane: dfd.bytesPlane,
      samples: dfd.samples.map((s) => ({
        bitOffset: s.bitOffset,
        bitLength: s.bitLength,
        channelType: s.channelType,
        samplePosition: s.samplePosition,
        // ktx-parse reads the bounds of signed samples as int32; report the raw 32-bit pattern.
        sampleLower: s.sampleLower >>> 0,
        sampleUpper: s.sampleUpper >>> 0,
      })),
    },
    keyValue: Object.fromEntries(Object.entries(container.keyValue).map(([key, value]) => [key, text(value)])),
    levels: container.levels.map((level) => {
      const data = level.levelData;
      const summary = {
        byteLength: data.byteLength,
        uncompressedByteLength: level.uncompressedByteLength,
        sha256: createHash('sha256').update(data).digest('hex'),
      };
      if (data.byteLength <= HEX_LIMIT) summary.hex = Buffer.from(data).toString('hex');
      return summary;
    }),
  };
}

const file = process.argv[2];
if (!file) {
  console.error('usage: node check_ktx2.mjs FILE.ktx2');
  process.exit(2);
}
try {
  console.log(JSON.stringify(summarize(read(new Uint8Array(readFileSync(file))))));
} catch (error) {
  console.error(`check_ktx2: ${file}: ${error.message}`);
  process.exit(1);
}
