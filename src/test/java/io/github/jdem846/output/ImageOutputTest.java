package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.Ellipsoid;
import io.github.jdem846.testing.TestDems;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import org.apache.sis.referencing.CRS;
import org.apache.sis.referencing.CommonCRS;
import org.apache.sis.util.Utilities;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.opengis.util.FactoryException;

/** The public entry point: sidecars, notices, and failures that must leave nothing behind. */
class ImageOutputTest {

    @TempDir
    Path dir;

    private static final CrsInfo WGS84 = CrsInfo.geographic("WGS 84", 4326, Ellipsoid.WGS84);
    private static final GeoReference GEO = new GeoReference(5.7, 50.2, 6.6, 49.4, WGS84);
    /** World file, .prj and .aux.xml next to a PNG (the default writes none). */
    private static final WriteOptions SIDECARS_FOR_PNG =
            WriteOptions.defaults().withSidecars(WriteOptions.Sidecars.WHEN_NOT_EMBEDDED);

    private List<String> listing() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void pngGetsWorldFilePrjAndAuxXml() throws IOException, FactoryException {
        Path png = dir.resolve("relief.png");
        WriteResult result = ImageOutput.writeRgba(png, new int[6], 3, 2, GEO, SIDECARS_FOR_PNG);
        assertEquals(List.of("relief.pgw", "relief.png", "relief.png.aux.xml", "relief.prj"), listing());
        assertEquals(png, result.image());
        assertEquals(List.of(dir.resolve("relief.pgw"), dir.resolve("relief.prj"), dir.resolve("relief.png.aux.xml")),
                result.sidecars());
        assertTrue(result.notices().isEmpty(), result.notices().toString());
        assertEquals(WorldFile.of(GEO, 3, 2).toText(), Files.readString(dir.resolve("relief.pgw")));
        String prj = Files.readString(dir.resolve("relief.prj"));
        // WGS 84 in east–north order (the world file's x = longitude), as a reader's CRS is
        assertTrue(Utilities.equalsIgnoreMetadata(CommonCRS.WGS84.normalizedGeographic(), CRS.fromWKT(prj.strip())),
                prj);
        assertTrue(Files.readString(dir.resolve("relief.png.aux.xml")).contains("<SRS dataAxisToSRSAxisMapping"));
    }

    @Test
    void wldNamingAndNoSidecars() throws IOException {
        ImageOutput.writeGray(dir.resolve("a.png"), new byte[4], 2, 2, GEO,
                SIDECARS_FOR_PNG.withWorldFileNaming(WriteOptions.WorldFileNaming.WLD));
        ImageOutput.writeGray(dir.resolve("b.png"), new byte[4], 2, 2, GEO, WriteOptions.defaults()); // none
        assertEquals(List.of("a.png", "a.png.aux.xml", "a.prj", "a.wld", "b.png"), listing());
    }

    @Test
    void geoTiffEmbedsGeoreferencingAndGetsSidecarsOnlyWhenAsked() throws IOException {
        ImageOutput.writeGray(dir.resolve("a.tif"), new byte[4], 2, 2, GEO, WriteOptions.defaults());
        ImageOutput.writeGray(dir.resolve("b.tiff"), new byte[4], 2, 2, GEO,
                WriteOptions.defaults().withSidecars(WriteOptions.Sidecars.ALWAYS));
        assertEquals(List.of("a.tif", "b.prj", "b.tfw", "b.tiff", "b.tiff.aux.xml"), listing());
    }

    @Test
    void unknownCrsGivesAWorldFileButNoPrjAndSaysSo() throws IOException {
        GeoReference local = new GeoReference(0, 100, 50, 0, CrsInfo.UNKNOWN);
        WriteResult result = ImageOutput.writeGray(dir.resolve("m.png"), new byte[2], 1, 2, local,
                SIDECARS_FOR_PNG);
        assertEquals(List.of("m.pgw", "m.png"), listing());
        assertEquals(1, result.notices().size());
        assertTrue(result.notices().get(0).contains("no .prj") && result.notices().get(0).contains("unknown"),
                result.notices().get(0));
    }

    @Test
    void staleSidecarsOfAnEarlierRunAreRemovedWithANotice() throws IOException {
        Path png = dir.resolve("r.png");
        ImageOutput.writeGray(png, new byte[4], 2, 2, GEO, SIDECARS_FOR_PNG);
        assertEquals(4, listing().size());
        // Same name, now without a known CRS: the old .prj and .aux.xml would lie about the new image.
        WriteResult unknown = ImageOutput.writeGray(png, new byte[4], 2, 2,
                new GeoReference(0, 1, 1, 0, CrsInfo.UNKNOWN), SIDECARS_FOR_PNG);
        assertEquals(List.of("r.pgw", "r.png"), listing());
        assertTrue(unknown.notices().stream().anyMatch(n -> n.contains("removed") && n.contains("r.prj")),
                unknown.notices().toString());
        // And without any georeferencing: the world file goes too.
        ImageOutput.writeGray(png, new byte[4], 2, 2, null, SIDECARS_FOR_PNG);
        assertEquals(List.of("r.png"), listing());
    }

    @Test
    void missingDirectoryIsAClearErrorAndWritesNothing() {
        Path file = dir.resolve("no/such/dir/out.png");
        IOException e = assertThrows(IOException.class,
                () -> ImageOutput.writeRgba(file, new int[1], 1, 1, GEO, WriteOptions.defaults()));
        assertTrue(e.getMessage().contains(file.toString()) && e.getMessage().contains("does not exist"),
                e.getMessage());
        assertFalse(Files.exists(dir.resolve("no")));
    }

    @Test
    void aFileInPlaceOfTheDirectoryIsAClearError() throws IOException {
        Files.writeString(dir.resolve("notadir"), "x");
        Path file = dir.resolve("notadir/out.tif");
        IOException e = assertThrows(IOException.class,
                () -> ImageOutput.writeGray(file, new byte[1], 1, 1, null, WriteOptions.defaults()));
        assertTrue(e.getMessage().contains("not a directory"), e.getMessage());
        assertEquals(List.of("notadir"), listing());
    }

    @Test
    void readOnlyExistingFileIsLeftUnchangedAndNothingElseIsWritten() throws IOException {
        Path png = dir.resolve("keep.png");
        Files.writeString(png, "old content");
        Files.setPosixFilePermissions(png, Set.of(PosixFilePermission.OWNER_READ, PosixFilePermission.GROUP_READ));
        try {
            IOException e = assertThrows(IOException.class,
                    () -> ImageOutput.writeRgba(png, new int[4], 2, 2, GEO, WriteOptions.defaults()));
            assertTrue(e.getMessage().contains(png.toString()) && e.getMessage().contains("read-only"),
                    e.getMessage());
            assertEquals("old content", Files.readString(png));
            assertEquals(List.of("keep.png"), listing()); // no sidecars, no temporary files
        } finally {
            Files.setPosixFilePermissions(png, Set.of(PosixFilePermission.OWNER_READ,
                    PosixFilePermission.OWNER_WRITE));
        }
    }

    @Test
    void readOnlySidecarStopsTheWholeWrite() throws IOException {
        Path prj = dir.resolve("s.prj");
        Files.writeString(prj, "old");
        Files.setPosixFilePermissions(prj, Set.of(PosixFilePermission.OWNER_READ));
        try {
            IOException e = assertThrows(IOException.class,
                    () -> ImageOutput.writeGray(dir.resolve("s.png"), new byte[1], 1, 1, GEO,
                            SIDECARS_FOR_PNG));
            assertTrue(e.getMessage().contains("s.prj"), e.getMessage());
            assertEquals(List.of("s.prj"), listing());
            assertEquals("old", Files.readString(prj));
        } finally {
            Files.setPosixFilePermissions(prj, Set.of(PosixFilePermission.OWNER_READ,
                    PosixFilePermission.OWNER_WRITE));
        }
    }

    @Test
    void unknownExtensionListsTheSupportedOnesAndWritesNothing() throws IOException {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ImageOutput.writeRgba(dir.resolve("out.gif"), new int[1], 1, 1, GEO, WriteOptions.defaults()));
        assertTrue(e.getMessage().contains("out.gif") && e.getMessage().contains(".png, .tif, .tiff, .jpg"),
                e.getMessage());
        assertEquals(List.of(), listing());
    }

    @Test
    void badInputIsRejectedBeforeAnythingIsWritten() throws IOException {
        IllegalArgumentException size = assertThrows(IllegalArgumentException.class,
                () -> ImageOutput.writeRgba(dir.resolve("a.png"), new int[5], 2, 3, null, WriteOptions.defaults()));
        assertTrue(size.getMessage().contains("5") && size.getMessage().contains("2×3"), size.getMessage());
        IllegalArgumentException floatPng = assertThrows(IllegalArgumentException.class,
                () -> ImageOutput.writeFloat(dir.resolve("a.png"), new float[1], 1, 1, null, WriteOptions.defaults()));
        assertTrue(floatPng.getMessage().contains("GeoTIFF"), floatPng.getMessage());
        IllegalArgumentException noData = assertThrows(IllegalArgumentException.class,
                () -> ImageOutput.writeGray(dir.resolve("a.tif"), new byte[1], 1, 1, null,
                        WriteOptions.defaults().withNoData(-9999)));
        assertTrue(noData.getMessage().contains("0..255"), noData.getMessage());
        assertThrows(IllegalArgumentException.class, () -> WriteOptions.defaults().withPngCompressionLevel(10));
        assertEquals(List.of(), listing());
    }

    @Test
    void replacingAFileGivesItTheUsualPermissionsOfANewFile() throws IOException {
        Path reference = Files.createFile(dir.resolve("reference"));
        Path png = dir.resolve("p.png");
        ImageOutput.writeGray(png, new byte[]{1}, 1, 1, null, WriteOptions.defaults());
        ImageOutput.writeGray(png, new byte[]{2}, 1, 1, null, WriteOptions.defaults());
        assertEquals(Files.getPosixFilePermissions(reference), Files.getPosixFilePermissions(png));
        assertEquals(2, javax.imageio.ImageIO.read(png.toFile()).getRaster().getSample(0, 0, 0));
    }

    @Test
    void imageSmallerThanTheDemKeepsTheDemsExtent() throws IOException {
        GeoReference geo = GeoReference.of(TestDems.load(TestDems.LUXEMBOURG).geometry());
        ImageOutput.writeRgba(dir.resolve("lux.png"), new int[10 * 9], 10, 9, geo, SIDECARS_FOR_PNG);
        double[] wf = Files.readAllLines(dir.resolve("lux.pgw")).stream().mapToDouble(Double::parseDouble)
                .toArray();
        // luxembourg: 95 × 90 cells of 0.008333…° from (5.741666…, 49.441666…): an image of 10 × 9 pixels
        double cell = 0.008333333333333337;
        assertArrayEquals(new double[]{95 * cell / 10, 0, 0, -90 * cell / 9, 5.741666666666666 + 95 * cell / 20,
                49.44166666666666 + 90 * cell - 90 * cell / 18}, wf, 1e-12);
    }
}
