//! Lists of indices stored one after another in one vector (compressed rows): the 3b-chains and
//! the crossing components, many of them of one or two triangles, without an allocation each.

/// Lists of indices, list after list.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Lists {
    /// The items of all lists, list after list.
    items: Vec<usize>,
    /// Where each list starts in `items`, then where the list being filled starts (so one entry
    /// more than there are closed lists; never empty).
    starts: Vec<usize>,
}

impl Lists {
    /// No list yet, room for `items` items in as many lists.
    pub fn with_capacity(items: usize) -> Lists {
        let mut starts = Vec::with_capacity(items + 1);
        starts.push(0);
        Lists {
            items: Vec::with_capacity(items),
            starts,
        }
    }

    /// Adds `item` to the last list (started by [`Lists::close`] or [`Lists::with_capacity`]).
    pub fn push(&mut self, item: usize) {
        self.items.push(item);
    }

    /// The number of items in the list being filled.
    pub fn open_len(&self) -> usize {
        self.items.len() - self.starts[self.len()]
    }

    /// Ends the list being filled; the next item starts a new one.
    pub fn close(&mut self) {
        self.starts.push(self.items.len());
    }

    /// The number of lists closed.
    pub fn len(&self) -> usize {
        self.starts.len() - 1
    }

    /// Whether no list is closed.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// List `i`.
    pub fn get(&self, i: usize) -> &[usize] {
        &self.items[self.starts[i]..self.starts[i + 1]]
    }

    /// Every list, in order.
    pub fn iter(&self) -> impl Iterator<Item = &[usize]> {
        self.starts.windows(2).map(|w| &self.items[w[0]..w[1]])
    }
}

#[cfg(test)]
mod tests {
    use super::Lists;

    #[test]
    fn lists_hold_their_items_in_order_and_may_be_empty() {
        let mut lists = Lists::with_capacity(4);
        assert!(lists.is_empty());
        for item in [7, 8] {
            lists.push(item);
        }
        assert_eq!(lists.open_len(), 2);
        lists.close();
        lists.close();
        lists.push(9);
        assert_eq!(lists.open_len(), 1);
        lists.close();
        assert_eq!(lists.len(), 3);
        assert_eq!(lists.get(0), &[7, 8]);
        assert!(lists.get(1).is_empty());
        let all: Vec<&[usize]> = lists.iter().collect();
        assert_eq!(all, vec![&[7, 8][..], &[], &[9]]);
    }
}
