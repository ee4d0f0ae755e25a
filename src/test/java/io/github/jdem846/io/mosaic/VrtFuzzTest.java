package io.github.jdem846.io.mosaic;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Timeout;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.testing.FuzzInputs;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Fuzz test of GDAL VRT mosaics ({@link VrtParser}, then the mosaic read): the XML, next to one real member
 * ({@code fuzz_member.tif}, testdata's 61 × 87 volcano GeoTIFF), reads or is refused with a DemFormatException
 * naming the .vrt or a member file the .vrt names. The normal test run replays
 * {@code src/test/resources/io/github/jdem846/io/mosaic/VrtFuzzTestInputs/vrt/}; {@code -Pfuzz} fuzzes
 * (docs/reliability.md).
 */
// a hang: more than 10 s for one input (Jazzer passes it to libFuzzer as -timeout when fuzzing)
@Timeout(value = 10, unit = TimeUnit.SECONDS)
class VrtFuzzTest {

    private static final byte[] MEMBER = testdata("dem/maungawhau-volcano_10m_nztm-approx.tif");

    @FuzzTest
    void vrt(byte[] data) throws Exception {
        Path member = FuzzInputs.write("fuzz_member.tif", MEMBER);
        Path vrt = FuzzInputs.write("fuzz_mosaic.vrt", data);
        // the names as the XML parser may have decoded them
        String text = new String(data, StandardCharsets.ISO_8859_1) + new String(data, StandardCharsets.UTF_8);
        FuzzInputs.readsOrRefuses(e -> {
            // the VRT, or a member it names (e.g. one that does not exist: "gone.tif: no such file")
            String m = e.getMessage();
            int colon = m.indexOf(": ");
            Path named = colon > 0 ? Path.of(m.substring(0, colon)) : null;
            if (named == null || named.getFileName() == null || named.equals(vrt)
                    || !text.contains(named.getFileName().toString())) {
                FuzzInputs.namesTheFile(vrt, m);
            }
        }, data.length, () -> DemReader.read(vrt));
    }

    private static byte[] testdata(String file) {
        try {
            return Files.readAllBytes(Path.of("testdata", file));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
