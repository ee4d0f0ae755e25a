package io.github.jdem846.io.mosaic;

import com.code_intelligence.jazzer.junit.FuzzTest;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.testing.FuzzInputs;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * Fuzz test of GDAL VRT mosaics ({@link VrtParser}, then the mosaic read): the XML, next to one real member
 * ({@code fuzz_member.tif}, testdata's 61 × 87 volcano GeoTIFF), reads or is refused with a DemFormatException
 * naming the .vrt or the member. The normal test run replays
 * {@code src/test/resources/io/github/jdem846/io/mosaic/VrtFuzzTestInputs/vrt/}; {@code -Pfuzz} fuzzes
 * (docs/reliability.md).
 */
class VrtFuzzTest {

    private static final byte[] MEMBER = testdata("dem/maungawhau-volcano_10m_nztm-approx.tif");

    @FuzzTest
    void vrt(byte[] data) throws Exception {
        Path member = FuzzInputs.write("fuzz_member.tif", MEMBER);
        Path vrt = FuzzInputs.write("fuzz_mosaic.vrt", data);
        FuzzInputs.readsOrRefuses(List.of(vrt, member), data.length, () -> DemReader.read(vrt));
    }

    private static byte[] testdata(String file) {
        try {
            return Files.readAllBytes(Path.of("testdata", file));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
