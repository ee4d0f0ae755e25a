package io.github.jdem846.io.mosaic;

import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.source.RasterSource;
import io.github.jdem846.io.source.ValueScale;
import java.io.IOException;
import java.nio.file.Path;

/**
 * What a mosaic needs to know of one file before reading any of its cells: its header, how its stored values
 * unpack, how its reader likes to be read. The file is opened to read these and closed again.
 *
 * @param given  the path as given (a {@code .hdr} stands for its data file)
 * @param data   the data file the reader opened
 * @param info   its header
 * @param scale  how its stored values unpack to elevations
 * @param traits how its reader likes to be read
 */
record MemberHeader(Path given, Path data, DemInfo info, ValueScale scale, ReadTraits traits) {

    static MemberHeader read(Path file, MemberOpener opener) throws IOException {
        try (RasterSource source = opener.open(file)) {
            return new MemberHeader(file, Path.of(source.info().source()), source.info(), source.valueScale(),
                    ReadTraits.of(source));
        }
    }
}
