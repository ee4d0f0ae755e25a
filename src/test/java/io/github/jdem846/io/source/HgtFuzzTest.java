package io.github.jdem846.io.source;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Timeout;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.testing.FuzzInputs;
import java.nio.file.Path;

/**
 * Fuzz test of SRTM {@code .hgt} tiles ({@link HgtFormat}): every sample value is an elevation, so what is fuzzed
 * is the file's length (only 1201² and 3601² samples of 2 bytes are tiles) and content. Reads or is refused naming
 * the file. The normal test run replays
 * {@code src/test/resources/io/github/jdem846/io/source/HgtFuzzTestInputs/hgt/}; {@code -Pfuzz} fuzzes
 * (docs/reliability.md).
 */
// a hang: more than 10 s for one input (Jazzer passes it to libFuzzer as -timeout when fuzzing)
@Timeout(value = 10, unit = TimeUnit.SECONDS)
class HgtFuzzTest {

    @FuzzTest
    void hgt(byte[] data) throws Exception {
        Path hgt = FuzzInputs.write("N36W112.hgt", data);
        FuzzInputs.readsOrRefuses(hgt, data.length, () -> DemReader.read(hgt));
    }
}
