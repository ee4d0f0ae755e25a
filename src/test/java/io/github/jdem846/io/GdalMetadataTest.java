package io.github.jdem846.io;

import io.github.jdem846.testing.TinyTiff;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.io.source.ValueScale;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A GDAL_METADATA tag (TIFF tag 42112) that is not XML is ignored with a notice, and nothing is printed on
 * stderr: the XML parser's default error handler printed "[Fatal Error] :1:1: Content is not allowed in prolog."
 * once per open of the file (26 times for one render).
 */
class GdalMetadataTest {

    private static final String NOTICE = "the GDAL_METADATA tag is not readable XML and was ignored";

    @TempDir
    Path tmp;

    /** What {@code action} prints on System.err (from any thread) while it runs. */
    private static String stderrOf(IoAction action) throws IOException {
        PrintStream saved = System.err;
        ByteArrayOutputStream captured = new ByteArrayOutputStream();
        System.setErr(new PrintStream(captured, true, StandardCharsets.UTF_8));
        try {
            action.run();
        } finally {
            System.setErr(saved);
        }
        return captured.toString(StandardCharsets.UTF_8);
    }

    @FunctionalInterface
    private interface IoAction {
        void run() throws IOException;
    }

    @Test
    void corruptMetadataIsANoticeAndPrintsNothing() throws IOException {
        // the words "scale" and "offset" make the reader parse the text
        for (String text : new String[] {"\u0001\u0002 role=\"scale\" garbage", "<not xml role=\"scale\"",
            "<GDALMetadata><Item role=\"offset\">1</Itm></GDALMetadata>", "scale"}) {
            Path tif = TinyTiff.int16(8, 8).ascii(42112, text).write(tmp, "meta.tif");
            List<DemInfo> infos = new ArrayList<>();
            String err = stderrOf(() -> {
                infos.add(DemReader.inspect(tif));
                infos.add(DemReader.load(tif, ReadRequest.FULL).info());
                assertEquals(64, DemReader.statistics(tif).validCount());
            });
            assertEquals("", err, "nothing on stderr for " + text);
            for (DemInfo info : infos) {
                assertTrue(info.notices().contains(NOTICE), info.notices().toString());
            }
        }
    }

    @Test
    void parserErrorsPrintNothingWhenCalledDirectly() throws IOException {
        List<String> notices = new ArrayList<>();
        String err = stderrOf(() -> assertTrue(ValueScale.fromGdalMetadata("<a role='scale'><b></a>", notices)
                .isIdentity()));
        assertEquals("", err);
        assertEquals(List.of(NOTICE), notices);
    }
}
