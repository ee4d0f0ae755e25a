package io.github.jdem846.output;

import java.io.Closeable;
import java.io.IOException;
import java.util.function.LongConsumer;

/**
 * Encodes one image file band of rows after band of rows, north to south: {@link PngWriter}, {@link GeoTiffWriter}
 * (strips) or {@link CogWriter}. The whole picture is one band.
 */
interface BandEncoder extends Closeable {

    /**
     * Encodes the next {@code band.height()} rows. The encoder is done with the band's arrays when this returns.
     *
     * @throws IllegalStateException when the rows would pass the bottom of the image
     */
    void append(Pixels band) throws IOException;

    /**
     * Completes the file, once every row was appended.
     *
     * @throws IllegalStateException when rows are missing
     */
    void finish() throws IOException;

    /** @return the rows the encoder writes in all, for progress: the image's height, for a COG every level's */
    long rowsToEncode();

    /**
     * From now on, tells {@code rows} how many rows each chunk written into the file held (a PNG segment, a TIFF
     * strip, a COG tile row of any level), in order, on the thread that appends.
     */
    void onEncoded(LongConsumer rows);

    /** Releases the file and any scratch files, finished or not (an unfinished file is incomplete). */
    @Override
    void close() throws IOException;
}
