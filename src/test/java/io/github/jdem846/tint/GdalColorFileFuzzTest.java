package io.github.jdem846.tint;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Timeout;
import io.github.jdem846.testing.FuzzInputs;
import java.nio.file.Path;

/**
 * Fuzz test of gdaldem colour files ({@link GdalColorFile}): a ramp, or a {@link ColorFileException} whose
 * message starts with the file. The normal test run replays
 * {@code src/test/resources/io/github/jdem846/tint/GdalColorFileFuzzTestInputs/colorFile/}; {@code -Pfuzz} fuzzes
 * (docs/reliability.md).
 */
// a hang: more than 10 s for one input (Jazzer passes it to libFuzzer as -timeout when fuzzing)
@Timeout(value = 10, unit = TimeUnit.SECONDS)
class GdalColorFileFuzzTest {

    @FuzzTest
    void colorFile(byte[] data) throws Exception {
        Path file = FuzzInputs.write("fuzz_colors.txt", data);
        for (ColorSelection selection : ColorSelection.values()) {
            try {
                if (GdalColorFile.read(file, selection) == null) {
                    throw new AssertionError("no ramp");
                }
            } catch (ColorFileException e) {
                if (!e.getMessage().startsWith(file.toString())) {
                    throw new AssertionError("the refusal does not name " + file + ": " + e.getMessage(), e);
                }
            }
        }
    }
}
