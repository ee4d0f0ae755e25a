package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.DemReader;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@link InputProtection}, {@link ImageOutput#filesWritten} and {@link DemReader#filesOf} together. */
class InputProtectionTest {

    private static final String STEM = "testdata/dem/maungawhau-volcano_10m_nztm-approx";

    @TempDir
    Path tmp;

    private Path gridFloat() throws IOException {
        for (String ext : new String[] {"flt", "hdr", "prj"}) {
            Files.copy(Path.of(STEM + "." + ext), tmp.resolve("g." + ext));
        }
        return tmp.resolve("g.flt");
    }

    /** World file, .prj and .aux.xml next to a PNG (the default writes none). */
    private static final WriteOptions SIDECARS_FOR_PNG =
            WriteOptions.defaults().withSidecars(WriteOptions.Sidecars.WHEN_NOT_EMBEDDED);

    @Test
    void theFilesOfAGridFloatAreItsDataHeaderAndPrj() throws IOException {
        Path flt = gridFloat();
        assertEquals(List.of(flt, tmp.resolve("g.hdr"), tmp.resolve("g.prj")), DemReader.filesOf(flt));
        // the header stands for its data file, and is listed too
        assertEquals(List.of(flt, tmp.resolve("g.hdr"), tmp.resolve("g.prj")),
                DemReader.filesOf(tmp.resolve("g.hdr")));
        Files.delete(tmp.resolve("g.prj"));
        assertEquals(List.of(flt, tmp.resolve("g.hdr")), DemReader.filesOf(flt));
        Path tif = Files.copy(Path.of(STEM + ".tif"), tmp.resolve("g.tif"));
        assertEquals(List.of(tif), DemReader.filesOf(tif));
    }

    @Test
    void filesWrittenFollowTheSidecarOption() {
        Path png = tmp.resolve("a.png");
        Path tif = tmp.resolve("a.tif");
        assertEquals(List.of(png), ImageOutput.filesWritten(png, WriteOptions.defaults()));
        assertEquals(List.of(tif), ImageOutput.filesWritten(tif, WriteOptions.defaults()));
        assertEquals(List.of(png, tmp.resolve("a.pgw"), tmp.resolve("a.prj"), tmp.resolve("a.png.aux.xml")),
                ImageOutput.filesWritten(png, SIDECARS_FOR_PNG));
        assertEquals(List.of(tif), ImageOutput.filesWritten(tif, SIDECARS_FOR_PNG));
        assertEquals(List.of(tif, tmp.resolve("a.wld"), tmp.resolve("a.prj"), tmp.resolve("a.tif.aux.xml")),
                ImageOutput.filesWritten(tif, WriteOptions.defaults().withSidecars(WriteOptions.Sidecars.ALWAYS)
                        .withWorldFileNaming(WriteOptions.WorldFileNaming.WLD)));
        assertEquals(List.of(png), ImageOutput.filesWritten(png,
                WriteOptions.defaults().withSidecars(WriteOptions.Sidecars.NONE)));
    }

    @Test
    void aSidecarThatIsAnInputFileIsRefusedWithBothNames() throws IOException {
        Path flt = gridFloat();
        OutputOverwritesInputException e = assertThrows(OutputOverwritesInputException.class,
                () -> InputProtection.check(tmp.resolve("g.png"), SIDECARS_FOR_PNG, DemReader.filesOf(flt)));
        assertEquals(tmp.resolve("g.prj"), e.output());
        assertEquals(tmp.resolve("g.prj"), e.input());
        assertTrue(e.getMessage().contains("a sidecar of " + tmp.resolve("g.png")), e.getMessage());
        // no sidecars: nothing of the input is touched
        assertDoesNotThrow(() -> InputProtection.check(tmp.resolve("g.png"),
                WriteOptions.defaults().withSidecars(WriteOptions.Sidecars.NONE), DemReader.filesOf(flt)));
    }

    @Test
    void hardLinksAndOtherSpellingsAreTheSameFile() throws IOException {
        Path flt = gridFloat();
        Path link = Files.createLink(tmp.resolve("copy.tif"), flt);
        OutputOverwritesInputException e = assertThrows(OutputOverwritesInputException.class,
                () -> InputProtection.check(link, WriteOptions.defaults(), DemReader.filesOf(flt)));
        assertEquals(link, e.output());
        assertEquals(flt, e.input());
        Files.createDirectory(tmp.resolve("sub"));
        Path other = tmp.resolve("sub/../g.png");
        Files.copy(Path.of(STEM + ".tif"), tmp.resolve("g.png"));   // an existing, unrelated file is fine
        assertThrows(OutputOverwritesInputException.class,
                () -> InputProtection.check(other, SIDECARS_FOR_PNG, DemReader.filesOf(flt)));
        assertDoesNotThrow(() -> InputProtection.check(other,
                WriteOptions.defaults().withSidecars(WriteOptions.Sidecars.NONE), DemReader.filesOf(flt)));
    }

    @Test
    void theSidecarsBesideAnInputDataFileAreNamedByTheGisConventions() {
        Path tif = tmp.resolve("dem.tif");
        assertEquals(List.of("dem.prj", "dem.hdr", "dem.wld", "dem.tif.aux.xml", "dem.aux.xml", "dem.tfw",
                "dem.tifw"), InputProtection.sidecarsOf(tif).stream().map(p -> p.getFileName().toString()).toList());
        assertEquals(List.of("g.prj", "g.hdr", "g.wld", "g.flt.aux.xml", "g.aux.xml", "g.ftw", "g.fltw"),
                InputProtection.sidecarsOf(tmp.resolve("g.flt")).stream().map(p -> p.getFileName().toString())
                        .toList());
        assertEquals(tmp, InputProtection.sidecarsOf(tif).get(0).getParent(), "beside the file");
    }

    @Test
    void aGeoTiffsWorldFileAndPrjAreProtectedThoughTheReaderIgnoresThem() throws IOException {
        Path tif = Files.copy(Path.of(STEM + ".tif"), tmp.resolve("dem.tif"));
        Files.copy(Path.of(STEM + ".prj"), tmp.resolve("dem.prj"));
        Files.writeString(tmp.resolve("dem.tfw"), "10\n0\n0\n-10\n0\n0\n");
        List<Path> inputs = DemReader.filesOf(tif);
        assertEquals(List.of(tif), inputs, "read from the GeoTIFF alone");
        OutputOverwritesInputException e = assertThrows(OutputOverwritesInputException.class,
                () -> InputProtection.check(tmp.resolve("dem.png"), SIDECARS_FOR_PNG, inputs));
        assertEquals(tmp.resolve("dem.prj"), e.output());
        assertTrue(e.getMessage().contains("a sidecar of the input file " + tif), e.getMessage());
        // a tile archive or any single file: the world file, through a relative spelling
        Path relative = Path.of("").toAbsolutePath().relativize(tmp.resolve("dem.tfw"));
        OutputOverwritesInputException one = assertThrows(OutputOverwritesInputException.class,
                () -> InputProtection.checkFile(relative, inputs));
        assertEquals(tmp.resolve("dem.tfw"), one.input());
        assertDoesNotThrow(() -> InputProtection.checkFile(tmp.resolve("dem.pmtiles"), inputs));
        assertDoesNotThrow(() -> InputProtection.check(tmp.resolve("other.png"), SIDECARS_FOR_PNG, inputs));
    }
}
